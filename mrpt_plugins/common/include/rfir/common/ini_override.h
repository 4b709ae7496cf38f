/* rfir: "section.key=value" edits written over an INI before it is read (the
 * apps' --set options, the experiment rows' INI edits). */
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace rfir::common {
/** One "section.key=value" edit, split. */
struct TIniEdit {
    std::string section, key, value;
};

/** Splits an edit: the section is what comes before the last '.' ahead of the
 * '='. Throws std::invalid_argument (a usage error) "INI edit (--set) '<edit>': expected
 * section.key=value" when malformed. */
TIniEdit parseIniEdit(const std::string& edit);

/** applyIniOverride for each edit, in order. */
void applyIniOverrides(mrpt::config::CConfigFileBase& ini,
                       const std::vector<std::string>& edits);

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
 * given. Throws std::invalid_argument naming the edit when it is malformed,
 * its section is known to no kind (or not to the prefix's), it is ambiguous,
 * or the prefix names no kind. Keys and values are checked by the loaders. */
std::vector<std::vector<std::string>> routeIniEdits(
    const std::vector<TIniKind>& kinds, const std::vector<std::string>& edits);
}  // namespace rfir::common
