/* rfir: the one exception type of command-line errors found after the parse
 * (a bad value, a --set edit the INI refuses, options that do not go
 * together). Every program exits kUsageExitCode (2) on it, before any work. */
#pragma once

#include <stdexcept>

namespace rfir::common {
/** Exit code of a command-line error (unknown option, bad value, ...). */
constexpr int kUsageExitCode = 2;

/** A command-line error; the message names the option. */
class CUsageError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};
}  // namespace rfir::common
