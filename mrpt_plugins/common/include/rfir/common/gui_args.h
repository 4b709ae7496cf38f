/* rfir: the live view's options (--gui, --gui-record, --gui-every), the same
 * in every program that has a view (docs/live-view.md). The view itself is
 * rfir::view, built only with MRPT's gui module (RFIR_WITH_GUI). */
#pragma once

#include <rfir/common/cli.h>

#include <string>

namespace rfir::common {
/** Steps between two drawn (and recorded) frames, unless --gui-every. */
constexpr unsigned kGuiEveryDefault = 10;

class CGuiArgs {
  public:
    explicit CGuiArgs(TCLAP::CmdLineInterface& cmd)
        : gui_("", "gui",
               "show the run live in a 3D window (needs a display; keys: space "
               "pause, s or right arrow one step, + / - speed, q or Esc close the "
               "view and finish the run)",
               cmd, false),
          record_("", "gui-record",
                  "also write the view's frames as DIR/frame_000001.png, ... (implies "
                  "--gui; headless: run under xvfb-run)",
                  false, "", "DIR", cmd),
          every_("", "gui-every",
                 "draw (and record) one frame every N steps (default " +
                     std::to_string(kGuiEveryDefault) + ")",
                 false, kGuiEveryDefault, "N", cmd, 1u, 1000000u) {}

    /** --gui or --gui-record given (TCLAP's getters are not const). */
    bool requested() { return gui_.getValue() || record_.isSet(); }
    std::string recordDir() { return record_.getValue(); }
    unsigned every() const { return every_.getValue(); }
    /** --gui-every without a view is a command-line error. */
    void check() {
        if (every_.isSet() && !requested())
            throw CUsageError("--gui-every: needs --gui or --gui-record");
        if (record_.isSet() && record_.getValue().empty())
            throw CUsageError("--gui-record: empty folder name");
    }

  private:
    TCLAP::SwitchArg gui_;
    TCLAP::ValueArg<std::string> record_;
    CNumberArg<unsigned> every_;
};

/** The message of --gui in a build without MRPT's gui module. */
inline std::string guiNotBuiltMessage(const std::string& program) {
    return "--gui: this " + program +
           " was built without the live view (MRPT's gui module or X11 was not found, or "
           "RFIR_WITH_GUI=OFF)";
}
}  // namespace rfir::common
