/* rfir: "section.key=value" edits written over an INI before it is read (the
 * apps' --set options, the experiment rows' INI edits). */
#pragma once

#include <rfir/common/usage_error.h>

#include <mrpt/config/CConfigFileBase.h>

#include <functional>
#include <string>
#include <vector>

namespace rfir::common {
/** One "section.key=value" edit, split. */
struct TIniEdit {
    std::string section, key, value;
};

/** Splits an edit: the section is what comes before the last '.' ahead of the
 * '='. Throws CUsageError "--set <edit>: expected section.key=value" when
 * malformed. */
TIniEdit parseIniEdit(const std::string& edit);

/** applyIniOverride for each edit, in order. */
void applyIniOverrides(mrpt::config::CConfigFileBase& ini,
                       const std::vector<std::string>& edits);

/** The load of an INI with a program's --set edits written over it:
 * `load(edits)` reads the INI, writes the edits it is given over it and
 * checks it, throwing on a bad key or value. Runs load(edits); when that
 * throws, the error is the command line's if the INI loads without the edits
 * (load({})): the first edit after which the load fails is to blame, and a
 * CUsageError "--set EDIT: [section] key: why" is thrown (without the INI's
 * file name: the value came from the command line). Otherwise the error is
 * the file's own and passes unchanged (naming the file; exit 1). A malformed
 * edit is a CUsageError before any load. */
void loadWithIniEdits(const std::vector<std::string>& edits,
                      const std::function<void(const std::vector<std::string>&)>& load);

/** One kind of INI a program reads: a name for the "KIND:" prefix, words for
 * messages ("simulation INIs") and the sections its loader knows. */
struct TIniKind {
    std::string name, description;
    std::vector<std::string> sections;
};

/** The --set edits of a program that reads several kinds of INI (e.g. the
 * simulator's and the SLAM filter's), split by kind: an edit goes to the kind
 * whose loader knows its section; "KIND:section.key=value" picks the kind,
 * which a section known to several kinds needs (e.g. [kidnap]). Returns, per
 * kind (in the order of `kinds`), its edits without the prefix, in the order
 * given. Throws CUsageError naming the edit when it is malformed,
 * its section is known to no kind (or not to the prefix's), it is ambiguous,
 * or the prefix names no kind. Keys and values are checked by the loaders. */
std::vector<std::vector<std::string>> routeIniEdits(
    const std::vector<TIniKind>& kinds, const std::vector<std::string>& edits);
}  // namespace rfir::common
