/* rfir-experiments: commands run as child processes, a fixed number at a time
 * (--jobs): each run in a process of its own, so that runs share no state. */
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rfir::experiments {
struct TChildCommand {
    std::string name;               //!< for messages, e.g. "t41 seed 2"
    std::vector<std::string> args;  //!< args[0]: the program to run
    std::string log;                //!< its stdout and stderr go to this file
};

/** Runs the commands, at most `width` at a time, in their order;
 * `done(i, seconds)` is called as command i exits with status 0. The first command that
 * fails (non-zero exit, signal, cannot start) stops the pool: the others still running
 * get SIGTERM and are waited for, then std::runtime_error names the command, its status
 * and the end of its log. Children get SIGTERM if this process dies. */
void runChildren(const std::vector<TChildCommand>& cmds, unsigned width,
                 const std::function<void(size_t, double)>& done);

/** The last `maxLines` lines of a text file ("" if unreadable). */
std::string fileTail(const std::string& path, size_t maxLines);

}  // namespace rfir::experiments
