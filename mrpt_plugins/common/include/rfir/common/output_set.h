/* rfir: the outputs of one run, and only of that run, in --out-dir. */
#pragma once

#include <string>
#include <vector>

namespace rfir::common {
/** A program's output folder, written as one set: files go into a fresh
 * staging folder "<outDir>.tmp.<pid>" beside it and commit() renames the set
 * into place, so that no file of an earlier run survives beside this run's
 * and a failed or killed run leaves the previous set (or nothing) in outDir. */
class COutputFolder {
  public:
    /** Refuses (std::runtime_error, before any work) an existing outDir that
     * holds an entry matching none of `patterns` (shell globs of the files the
     * program writes): such files are not the program's to replace. */
    COutputFolder(std::string outDir, std::vector<std::string> patterns,
                  std::string program);
    ~COutputFolder();  //!< removes the staging folder unless committed
    COutputFolder(const COutputFolder&) = delete;
    COutputFolder& operator=(const COutputFolder&) = delete;

    /** Where to write `name` (a plain file name); recorded in files(). */
    std::string file(const std::string& name);
    /** The names given to file() so far, sorted. */
    std::vector<std::string> files() const;
    /** Exchanges the staging folder with an earlier set in one atomic rename
     * (RENAME_EXCHANGE; else moves the earlier set aside first), then removes
     * the earlier set. */
    void commit();

  private:
    void removeLeftovers() const;
    std::string outDir_, staging_, program_;
    std::vector<std::string> files_;
    bool committed_ = false;
};

/** The files of one output set named `stem` inside a folder shared with other
 * sets (rfir-sim's datasets: "<stem>.rawlog", "<stem>.gt.tum", ...): staged in
 * "<dir>/.<stem>.tmp.<pid>", and commit() removes every earlier file of the set
 * (matching `patterns`, globs relative to dir) before renaming the new ones in. */
class COutputFiles {
  public:
    COutputFiles(std::string dir, std::vector<std::string> patterns);
    ~COutputFiles();
    COutputFiles(const COutputFiles&) = delete;
    COutputFiles& operator=(const COutputFiles&) = delete;
    std::string file(const std::string& name);
    void commit();

  private:
    std::string dir_, staging_;
    std::vector<std::string> patterns_, files_;
    bool committed_ = false;
};

/** The identity of a run for settings.ini / stats.json: this process's
 * command line (from /proc/self/cmdline), and the MD5 of a file's bytes. */
std::string processCommandLine();
std::string fileMD5(const std::string& path);
/** The project's version, RFIR_VERSION (rfir/version.h). */
std::string rfirVersion();
/** A JSON object {"command": ..., "version": ..., "seed": N, "ini": path,
 * "ini_md5": ..., "files": [...]} for stats.json. */
std::string runIdentityJson(uint64_t seed, const std::string& iniPath,
                            const std::vector<std::string>& files);

}  // namespace rfir::common
