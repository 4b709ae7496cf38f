/* rfir: map and ground-truth files of textlog.md: `tag <id> <x> <y> [<sx> <sy>]`,
 * `emitter <id> <x> <y> <z> [<sx> <sy>]`, `landmark <id> <x> <y> [<sx> <sy>]`. */
#pragma once

#include <rfir/obs/ir_lattice.h>

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace rfir::common {
struct TMapEntry {
    enum class Kind { Tag, Emitter, Landmark };
    Kind kind = Kind::Tag;
    std::string id;
    double x = 0, y = 0, z = 0;    //!< z only for emitters
    std::optional<double> sx, sy;  //!< standard deviations (estimated maps)
    /** rfir-slam's PF/PS maps, after sx sy: the tag's reads and how many of
     * them its estimate at the time contradicted (docs/import.md). */
    std::optional<uint64_t> reads{}, contradicted{};
    int line = 0;  //!< line in the file it was read from (0: not read from a file)
};
using TMapFile = std::vector<TMapEntry>;

/** True if `id` is a valid textlog ID: [A-Za-z0-9_.:-], 1..64 characters. */
bool isValidId(const std::string& id);

/** Writes atomically, one record per line, with sx sy when present, then
 * the read counts when present. */
void saveMapFile(const std::string& path, const TMapFile& m,
                 const std::string& headerComment = {});
/** Reads a map / ground-truth file. Throws std::runtime_error("FILE:LINE: ...")
 * on a malformed line, an unknown record, a bad ID or a duplicate ID of one kind
 * (except repeated-ID emitters, IDs 1..9, which recur by design). */
TMapFile loadMapFile(const std::string& path);
/** Same from a stream; `name` is used in messages. */
TMapFile loadMapFile(std::istream& in, const std::string& name);

/** `emitter` records of emitters (id, x, y, z), in their order. */
TMapFile emitterEntries(const std::vector<rfir::ir::TEmitter>& emitters);

}  // namespace rfir::common
