/* rfir: the known emitter map. */
#include <rfir/common/map_io.h>
#include <rfir/ir/emitter_set.h>
#include <rfir/obs/ir_codes.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir::ir {
namespace {
/** Largest |coordinate| of an emitter (m): beyond any building. */
constexpr double kMaxEmitterCoordinate = 1e6;

std::string checkId(const TEmitter& e) {
    const auto codes = codesFromEmitterId(e.id);
    if (!codes)
        return "emitter ID '" + e.id +
               "' is not an ascending set of frequency codes 1..9 (e.g. 1, 39, 257)";
    if (*codes != e.codes) return "emitter ID '" + e.id + "' does not match its codes";
    return {};
}
}  // namespace

TEmitterSet::TEmitterSet(std::vector<TEmitter> emitters)
    : m_emitters(std::move(emitters)) {
    for (size_t i = 0; i < m_emitters.size(); i++) {
        auto& e = m_emitters[i];
        if (e.codes.empty())
            if (const auto c = codesFromEmitterId(e.id)) e.codes = *c;
        const std::string err = checkId(e);
        if (!err.empty()) throw std::invalid_argument(err);
        e.repeated = isRepeatedId(e.codes);
        auto& list = m_byId[e.id];
        if (!e.repeated && !list.empty())
            throw std::invalid_argument("unique emitter ID '" + e.id + "' used twice");
        list.push_back(i);
    }
    buildGrid();
}

TEmitterSet TEmitterSet::load(const std::string& path) {
    return fromMapEntries(rfir::common::loadMapFile(path), path);
}

TEmitterSet TEmitterSet::fromMapEntries(const rfir::common::TMapFile& records,
                                        const std::string& path,
                                        const std::vector<std::string>& absent) {
    std::vector<TEmitter> em;
    for (const auto& r : records) {
        if (r.kind != rfir::common::TMapEntry::Kind::Emitter) continue;
        if (std::find(absent.begin(), absent.end(), r.id) != absent.end()) continue;
        TEmitter e;
        e.id = r.id;
        e.x = r.x;
        e.y = r.y;
        e.z = r.z;
        if (const auto c = codesFromEmitterId(r.id)) e.codes = *c;
        std::string err = checkId(e);
        if (err.empty() && !(std::abs(e.x) <= kMaxEmitterCoordinate &&
                             std::abs(e.y) <= kMaxEmitterCoordinate &&
                             std::abs(e.z) <= kMaxEmitterCoordinate))
            err = "emitter '" + e.id + "': coordinates must be within +-1e6 m";
        if (!err.empty())
            throw std::runtime_error(path + ":" + std::to_string(r.line) + ": " + err);
        em.push_back(e);
    }
    if (em.empty()) throw std::runtime_error(path + ": no emitter record in the file");
    return TEmitterSet(std::move(em));
}

const std::vector<size_t>* TEmitterSet::candidates(const std::string& id) const {
    const auto it = m_byId.find(id);
    return it == m_byId.end() ? nullptr : &it->second;
}

bool TEmitterSet::isUnambiguous(const std::string& id) const {
    const auto* c = candidates(id);
    return c && c->size() == 1;
}

size_t TEmitterSet::uniqueEmitterCount() const {
    return size_t(std::count_if(m_emitters.begin(), m_emitters.end(),
                                [](const TEmitter& e) { return !e.repeated; }));
}

size_t TEmitterSet::repeatedEmitterCount() const {
    return m_emitters.size() - uniqueEmitterCount();
}

void TEmitterSet::bounds(double& x0, double& y0, double& x1, double& y1) const {
    x0 = m_x0;
    y0 = m_y0;
    x1 = m_x1;
    y1 = m_y1;
}

}  // namespace rfir::ir

namespace rfir::ir {
void TEmitterSet::buildGrid() {
    m_grid.reset(kGridCell);
    for (size_t i = 0; i < m_emitters.size(); i++) {
        const auto& e = m_emitters[i];
        if (i == 0 || e.x < m_x0) m_x0 = e.x;
        if (i == 0 || e.y < m_y0) m_y0 = e.y;
        if (i == 0 || e.x > m_x1) m_x1 = e.x;
        if (i == 0 || e.y > m_y1) m_y1 = e.y;
    }
    for (size_t i = 0; i < m_emitters.size(); i++)
        m_grid.insert(m_emitters[i].x, m_emitters[i].y, i);
}

std::optional<size_t> TEmitterSet::nearestIndexWithin(double x, double y,
                                                      double radius) const {
    double best = radius * radius;
    std::optional<size_t> found;
    // Ties go to the last one visited (the grid's fixed order).
    m_grid.forEachAround(x, y, [&](size_t i) {
        const double dx = m_emitters[i].x - x, dy = m_emitters[i].y - y;
        const double d2 = dx * dx + dy * dy;
        if (d2 <= best) {
            best = d2;
            found = i;
        }
    });
    return found;
}
}  // namespace rfir::ir
