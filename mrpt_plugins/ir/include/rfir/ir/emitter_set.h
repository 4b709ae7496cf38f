/* rfir: the known emitter map of the IR system (thesis 5.1): unique-ID
 * emitters (LED arrays, code combinations, one place each) and repeated-ID
 * emitters (one LED, one code, many places). */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/models/spatial_grid.h>
#include <rfir/obs/ir_lattice.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rfir::ir {
class TEmitterSet {
  public:
    TEmitterSet() = default;
    /** Throws std::invalid_argument on an ID that is not an ascending set of
     * codes 1..9, or a multi-code (unique) ID used twice. */
    explicit TEmitterSet(std::vector<TEmitter> emitters);

    /** Reads the `emitter <id> <x> <y> <z>` records of a map file (other
     * records, e.g. the tags of a ground-truth map, are skipped). Throws
     * std::runtime_error("FILE:LINE: ...") on a malformed line or a bad ID, and
     * "FILE: no emitter" when there is none. */
    static TEmitterSet load(const std::string& path);
    /** The same from records already read (`source` names their file in the
     * messages), leaving out the emitters whose ID is in `absent`. */
    static TEmitterSet fromMapEntries(const rfir::common::TMapFile& records,
                                      const std::string& source,
                                      const std::vector<std::string>& absent = {});

    const std::vector<TEmitter>& emitters() const { return m_emitters; }
    bool empty() const { return m_emitters.empty(); }
    /** Emitters carrying an ID (indices into emitters()); nullptr if unknown. */
    const std::vector<size_t>* candidates(const std::string& id) const;
    /** True if exactly one emitter carries the ID (its reading places the robot
     * without any prior: the thesis' "unique ID"). */
    bool isUnambiguous(const std::string& id) const;

    size_t uniqueEmitterCount() const;    //!< emitters with >= 2 codes
    size_t repeatedEmitterCount() const;  //!< emitters with 1 code
    size_t distinctIdCount() const { return m_byId.size(); }
    /** Bounding box of the emitters (x0, y0, x1, y1); zeros when empty. */
    void bounds(double& x0, double& y0, double& x1, double& y1) const;
    /** Index of the emitter nearest to (x, y), if one lies within `radius`
     * (<= kGridCell) of it; a grid lookup, O(1). */
    std::optional<size_t> nearestIndexWithin(double x, double y, double radius) const;
    /** Cell side of the lookup grid (m): the largest radius nearestIndexWithin takes. */
    static constexpr double kGridCell = 0.5;

  private:
    void buildGrid();
    std::vector<TEmitter> m_emitters;
    std::map<std::string, std::vector<size_t>> m_byId;
    rfir::models::TSpatialGrid<size_t> m_grid{kGridCell};
    double m_x0 = 0, m_y0 = 0, m_x1 = 0, m_y1 = 0;  //!< cached bounds
};

}  // namespace rfir::ir
