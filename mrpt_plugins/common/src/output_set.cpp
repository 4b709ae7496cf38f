/* rfir: the outputs of one run, staged and renamed into place. */
#include <rfir/common/output_set.h>

#include <rfir/common/json.h>
#include <rfir/version.h>

#include <mrpt/system/md5.h>

#include <fcntl.h>
#include <fnmatch.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace rfir::common {
namespace {
bool matchesAny(const std::string& name, const std::vector<std::string>& patterns) {
    for (const auto& p : patterns)
        if (fnmatch(p.c_str(), name.c_str(), 0) == 0) return true;
    return false;
}

std::string pidSuffix() {
    return std::to_string(::getpid());
}

void freshFolder(const std::string& dir) {
    std::error_code ec;
    fs::remove_all(dir, ec);  // a folder left by a killed run of the same pid
    if (!fs::create_directories(dir, ec) && !fs::is_directory(dir))
        throw std::runtime_error("cannot create the staging folder '" + dir + "'");
}

std::string recordName(std::vector<std::string>& files, const std::string& dir,
                       const std::string& name) {
    if (name.empty() || name.find('/') != std::string::npos)
        throw std::logic_error("output name '" + name + "' is not a plain file name");
    if (std::find(files.begin(), files.end(), name) == files.end()) files.push_back(name);
    return (fs::path(dir) / name).string();
}

std::vector<std::string> sorted(std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
}
}  // namespace

COutputFolder::COutputFolder(std::string outDir, std::vector<std::string> patterns,
                             std::string program)
    : outDir_(fs::path(std::move(outDir)).lexically_normal().string()),
      program_(std::move(program)) {
    while (outDir_.size() > 1 && outDir_.back() == '/') outDir_.pop_back();
    if (fs::exists(outDir_)) {
        if (!fs::is_directory(outDir_))
            throw std::runtime_error(outDir_ + ": not a folder");
        for (const auto& e : fs::directory_iterator(outDir_)) {
            const std::string n = e.path().filename().string();
            if (!e.is_regular_file() || !matchesAny(n, patterns))
                throw std::runtime_error(
                    outDir_ + " holds '" + n + "', which " + program_ +
                    " does not write: give a new folder or one of " + program_ +
                    "'s output folders (the whole folder is replaced)");
        }
    }
    removeLeftovers();
    staging_ = outDir_ + ".tmp." + pidSuffix();
    freshFolder(staging_);
}

COutputFolder::~COutputFolder() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

std::string COutputFolder::file(const std::string& name) {
    return recordName(files_, staging_, name);
}

std::vector<std::string> COutputFolder::files() const {
    return sorted(files_);
}

/** The folders "<outDir>.tmp.<pid>" / "<outDir>.old.<pid>" that runs killed
 * before the end left (their pid is gone). A killed commit of the two-rename
 * fallback leaves outDir missing and the earlier set in ".old.": put back. */
void COutputFolder::removeLeftovers() const {
    const fs::path dir = fs::path(outDir_).parent_path().empty()
                             ? fs::path(".")
                             : fs::path(outDir_).parent_path();
    const std::string base = fs::path(outDir_).filename().string();
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string n = e.path().filename().string();
        for (const std::string kind : {".tmp.", ".old."}) {
            if (n.rfind(base + kind, 0) != 0) continue;
            const std::string pid = n.substr(base.size() + kind.size());
            if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos ||
                pid.size() > 9)
                continue;
            if (::kill(std::stoi(pid), 0) == 0 || errno != ESRCH) continue;  // alive
            std::error_code ec2;
            if (kind == ".old." && !fs::exists(outDir_))
                fs::rename(e.path(), outDir_, ec2);
            else
                fs::remove_all(e.path(), ec2);
        }
    }
}

void COutputFolder::commit() {
    std::error_code ec;
    // One atomic exchange when the folder exists: outDir always holds one
    // whole set, even if the process is killed here.
    if (fs::is_directory(outDir_) && ::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD,
                                                 outDir_.c_str(), RENAME_EXCHANGE) == 0) {
        committed_ = true;
        fs::remove_all(staging_, ec);  // now the earlier set
        return;
    }
    // No folder yet, or a file system without RENAME_EXCHANGE: two renames.
    const std::string old = outDir_ + ".old." + pidSuffix();
    fs::remove_all(old, ec);
    const bool hadOld = fs::exists(outDir_);
    if (hadOld) fs::rename(outDir_, old);  // throws naming the folders
    try {
        fs::rename(staging_, outDir_);
    } catch (...) {
        if (hadOld) fs::rename(old, outDir_, ec);  // put the earlier set back
        throw;
    }
    committed_ = true;
    if (hadOld) fs::remove_all(old, ec);
}

COutputFiles::COutputFiles(std::string dir, std::vector<std::string> patterns)
    : dir_(std::move(dir)), patterns_(std::move(patterns)) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (!fs::is_directory(dir_))
        throw std::runtime_error(dir_ + ": cannot create the output folder");
    staging_ = (fs::path(dir_) / (".rfir.tmp." + pidSuffix())).string();
    freshFolder(staging_);
}

COutputFiles::~COutputFiles() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

std::string COutputFiles::file(const std::string& name) {
    return recordName(files_, staging_, name);
}

void COutputFiles::commit() {
    // The earlier set goes first: its files this run does not write (e.g. a
    // .spots.tum) must not stay beside the new ones.
    for (const auto& e : fs::directory_iterator(dir_))
        if (e.is_regular_file() && matchesAny(e.path().filename().string(), patterns_))
            fs::remove(e.path());
    for (const auto& n : files_) fs::rename(fs::path(staging_) / n, fs::path(dir_) / n);
    committed_ = true;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

std::string processCommandLine() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string raw((std::istreambuf_iterator<char>(in)),
                    std::istreambuf_iterator<char>());
    std::string out;
    std::istringstream parts(raw);
    std::string a;
    while (std::getline(parts, a, '\0')) {
        const bool plain =
            !a.empty() && a.find_first_of(" \t'\"\\$") == std::string::npos;
        out += (out.empty() ? "" : " ") + (plain ? a : "'" + a + "'");
    }
    return out;
}

std::string fileMD5(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    const std::string bytes((std::istreambuf_iterator<char>(in)),
                            std::istreambuf_iterator<char>());
    return mrpt::system::md5(bytes);
}

std::string rfirVersion() {
    return RFIR_VERSION;
}

std::string runIdentityJson(uint64_t seed, const std::string& iniPath,
                            const std::vector<std::string>& files) {
    TJson j;
    j["command"] = processCommandLine();
    j["version"] = rfirVersion();
    j["seed"] = seed;
    j["ini"] = iniPath;
    j["ini_md5"] = fileMD5(iniPath);
    j["files"] = files;
    return dumpJson(j);
}

}  // namespace rfir::common
