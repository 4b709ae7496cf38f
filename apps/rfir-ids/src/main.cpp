/* rfir-ids: IR emitter IDs (thesis 5.1, 5.3).
 *   rfir-ids encode --codes 3,9           -> 39
 *   rfir-ids decode --id 39               -> codes, frequencies, type
 *   rfir-ids count [--frequencies 30 --max-codes 6]   -> 768211
 *   rfir-ids plan --room "0 0 3.2 2.4" [--pitch 0.8] [--output emitters.txt]
 *   rfir-ids memory --grid "600 400" [--repeated-ids 9]  -> thesis 5.3 sizes */
#include <rfir/common/cli.h>
#include <rfir/common/map_io.h>
#include <rfir/ir/id_planner.h>
#include <rfir/obs/ir_codes.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>
#include <sstream>

using namespace rfir::ir;
using rfir::common::CNumberArg;
using rfir::common::CUsageError;

namespace {
struct TArgs {
    TCLAP::CmdLine cmd{"rfir-ids: IR emitter ID scheme and emitter layout planner", ' ',
                       RFIR_VERSION};
    rfir::common::CSubcommandArg command{
        "command", {"encode", "decode", "count", "plan", "memory"}, cmd};
    TCLAP::ValueArg<std::string> codes{
        "", "codes", "encode: codes, e.g. 3,9", false, "", "LIST", cmd};
    TCLAP::ValueArg<std::string> id{"",   "id", "decode: emitter ID, e.g. 39", false, "",
                                    "ID", cmd};
    // 60 keeps every binomial sum of countIds within 64 bits.
    CNumberArg<int> freqs{"",
                          "frequencies",
                          "count: number of frequencies (1-60)",
                          false,
                          kNumCodes,
                          "N",
                          cmd,
                          1,
                          60};
    CNumberArg<int> maxCodes{
        "",    "max-codes", "count: most codes per ID (microcontroller pins, 1-60)",
        false, kNumCodes,   "K",
        cmd,   1,           60};
    TCLAP::ValueArg<std::string> room{
        "", "room", "plan: \"min_x min_y max_x max_y\" (m)", false, "", "BOX", cmd};
    CNumberArg<double> pitch{
        "", "pitch", "plan: same-type emitter spacing (m)", false, 0.8, "M", cmd, 0};
    CNumberArg<double> height{
        "", "height", "plan: emitter height above floor (m)", false, 1.5, "M", cmd, 0};
    TCLAP::ValueArg<std::string> repCodes{
        "", "repeated-codes", "plan: codes of the repeated IDs", false, "1,2,3,4", "LIST",
        cmd};
    CNumberArg<int> uniqueCodes{
        "", "unique-codes", "plan: codes per unique ID (2-9)", false, 2, "K", cmd, 2, 9};
    TCLAP::SwitchArg allUnique{
        "", "all-unique", "plan: the same positions, every emitter a unique ID", cmd};
    TCLAP::ValueArg<std::string> out{
        "o", "output", "plan: emitter file to write", false, "", "FILE", cmd};
    TCLAP::ValueArg<std::string> grid{
        "", "grid", "memory: \"L W\" repeated grid lines", false, "", "L W", cmd};
    CNumberArg<uint64_t> repIds{
        "", "repeated-ids",  "memory: repeated IDs used", false, 9, "N", cmd,
        0,  1000000000000ULL};
    TCLAP::SwitchArg quiet{"q", "quiet", rfir::common::kQuietHelp, cmd};
};

int cmdEncode(TArgs& a) {
    const auto c = parseCodeList(a.codes.getValue());
    if (!c)
        throw CUsageError("--codes: '" + a.codes.getValue() +
                          "' is not an ascending list of codes 1..9 (e.g. 3,9)");
    std::cout << emitterIdFromCodes(*c) << "\n";
    return 0;
}

int cmdDecode(TArgs& a) {
    const auto c = codesFromEmitterId(a.id.getValue());
    if (!c)
        throw CUsageError("--id: '" + a.id.getValue() +
                          "' is not an emitter ID (ascending digits 1..9)");
    std::cout << "id " << a.id.getValue() << "\ncodes " << formatCodeList(*c)
              << "\nfrequencies_hz";
    for (auto k : *c) std::cout << " " << codeFrequencyHz(k);
    std::cout << "\ntype " << (isRepeatedId(*c) ? "repeated" : "unique") << "\n";
    return 0;
}

int cmdPlan(TArgs& a) {
    if (!a.room.isSet()) throw CUsageError("plan: --room is required");
    const auto b =
        rfir::common::parseNumberList<double>("--room", a.room.getValue(), ' ', 4);
    TRoom room{b[0], b[1], b[2], b[3]};
    TLatticeParams p;
    p.pitch = a.pitch.getValue();
    p.height = a.height.getValue();
    const auto rc = parseCodeList(a.repCodes.getValue());
    if (!rc) throw CUsageError("--repeated-codes: not an ascending list of 1..9");
    p.repeatedCodes = *rc;
    p.uniqueCodesPerId = a.uniqueCodes.getValue();
    p.allUnique = a.allUnique.getValue();
    const auto r = planLattice(room, p);
    std::cout << formatPlanReport(r);
    if (a.out.isSet()) {
        const auto f = rfir::common::emitterEntries(r.emitters);
        rfir::common::saveMapFile(a.out.getValue(), f,
                                  "rfir-ids plan --room \"" + a.room.getValue() +
                                      "\" --pitch " + std::to_string(p.pitch));
        std::cout << "wrote " << a.out.getValue() << "\n";
    }
    return 0;
}

int cmdMemory(TArgs& a) {
    if (!a.grid.isSet()) throw CUsageError("memory: --grid is required");
    // Bounded so that the record counts stay within 64 bits.
    const auto g = rfir::common::parseNumberList<uint64_t>("--grid", a.grid.getValue(),
                                                           ' ', 2, 2, 1000000);
    const uint64_t L = g[0], W = g[1];
    std::cout << "mixed layout records:       "
              << mixedLayoutRecords(L, W, a.repIds.getValue())
              << "\nunique-only layout records: " << uniqueOnlyLayoutRecords(L, W)
              << "\n";
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    TArgs a;
    try {
        if (const auto code = rfir::common::parseCommandLine(a.cmd, argc, argv,
                                                             {{"--out", "--output"}}))
            return *code;
        // --quiet: every result line is dropped (a stream without a buffer
        // writes nothing); errors still go to stderr.
        if (a.quiet.getValue()) std::cout.rdbuf(nullptr);
        const std::string c = a.command.getValue();
        if (c == "encode") return cmdEncode(a);
        if (c == "decode") return cmdDecode(a);
        if (c == "count") {
            std::cout << countIds(a.freqs.getValue(), a.maxCodes.getValue()) << "\n";
            return 0;
        }
        if (c == "plan") return cmdPlan(a);
        return cmdMemory(a);          // CSubcommandArg took no other name
    } catch (const CUsageError& e) {  // thrown before the command's output
        std::cerr << "rfir-ids: error: " << e.what() << "\n";
        return rfir::common::kUsageExitCode;
    } catch (const std::exception& e) {
        std::cerr << "rfir-ids: error: " << e.what() << "\n";
        return 1;
    }
}
