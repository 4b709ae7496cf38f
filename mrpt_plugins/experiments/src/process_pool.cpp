/* rfir-experiments: child processes, a fixed number at a time. */
#include <rfir/experiments/process_pool.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <stdexcept>

namespace rfir::experiments {
namespace {
/** fork + exec: between the two only async-signal-safe calls. */
pid_t start(const TChildCommand& c) {
    std::vector<char*> argv;
    for (const auto& a : c.args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int fd = ::open(c.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        throw std::runtime_error(c.name + ": cannot create its log '" + c.log +
                                 "': " + std::strerror(errno));
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);       // no orphan runs if we die
        if (::getppid() != parent) ::_exit(127);  // died before prctl
        const int in = ::open("/dev/null", O_RDONLY);
        if (in < 0 || ::dup2(in, 0) < 0 || ::dup2(fd, 1) < 0 || ::dup2(fd, 2) < 0)
            ::_exit(127);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    const int err = errno;
    ::close(fd);
    if (pid < 0)
        throw std::runtime_error(c.name + ": cannot start it: " + std::strerror(err));
    return pid;
}

std::string statusText(int st) {
    if (WIFEXITED(st))
        return WEXITSTATUS(st) == 127 ? "exit 127: could not be started"
                                      : "exit " + std::to_string(WEXITSTATUS(st));
    if (WIFSIGNALED(st))
        return "killed by signal " + std::to_string(WTERMSIG(st)) + ", " +
               ::strsignal(WTERMSIG(st));
    return "status " + std::to_string(st);
}

void stopAll(std::map<pid_t, size_t>& running) {
    for (const auto& [pid, i] : running) ::kill(pid, SIGTERM);
    for (const auto& [pid, i] : running)
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    running.clear();
}
}  // namespace

std::string fileTail(const std::string& path, size_t maxLines) {
    std::ifstream in(path);
    std::deque<std::string> lines;
    for (std::string l; std::getline(in, l);) {
        lines.push_back(l.size() > 2000 ? l.substr(0, 2000) + "..." : l);
        if (lines.size() > maxLines) lines.pop_front();
    }
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

void runChildren(const std::vector<TChildCommand>& cmds, unsigned width,
                 const std::function<void(size_t, double)>& done) {
    using Clock = std::chrono::steady_clock;
    std::map<pid_t, size_t> running;  // pid -> command
    std::vector<Clock::time_point> t0(cmds.size());
    size_t next = 0;
    try {
        while (next < cmds.size() || !running.empty()) {
            while (running.size() < std::max(width, 1u) && next < cmds.size())
                t0[next] = Clock::now(), running[start(cmds[next])] = next, next++;
            int st = 0;
            const pid_t pid = ::waitpid(-1, &st, 0);
            if (pid < 0) {
                if (errno == EINTR) continue;
                throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
            }
            const auto it = running.find(pid);
            if (it == running.end()) continue;  // not one of ours
            const size_t i = it->second;
            running.erase(it);
            if (WIFEXITED(st) && WEXITSTATUS(st) == 0) {
                done(i, std::chrono::duration<double>(Clock::now() - t0[i]).count());
                continue;
            }
            const std::string tail = fileTail(cmds[i].log, 20);
            throw std::runtime_error(cmds[i].name + " failed (" + statusText(st) + ")" +
                                     (tail.empty() ? "" : "; its output ends:\n" + tail));
        }
    } catch (...) {
        stopAll(running);
        throw;
    }
}

}  // namespace rfir::experiments
