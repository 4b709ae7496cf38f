/* rfir: CRFIDTagParticleMap: a prior map read from a map text file (MRPT's
 * pf-localization localizes against a map it is given, never inserts into). */
#include "CRFIDTagParticleMap_impl.h"

#include <mrpt/random/RandomGenerators.h>
#include <rfir/models/random.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

using namespace rfir::maps;

namespace {
/** A `tag`/`landmark` record: id, mean and standard deviations (0: none). */
struct TPriorRecord {
    std::string kind, id;
    double x = 0, y = 0, sx = 0, sy = 0;
    /** map.txt's read counts, if given: the reads that agreed with the tag. */
    std::optional<uint64_t> agreed;
};

TPriorRecord parseRecord(const std::string& line, const std::string& where) {
    std::istringstream in(line);
    TPriorRecord r;
    in >> r.kind >> r.id >> r.x >> r.y;
    if (!in) throw std::runtime_error(where + ": expected '" + r.kind + " <id> <x> <y>'");
    if (in >> r.sx) {
        if (!(in >> r.sy) || !(r.sx >= 0) || !(r.sy >= 0))
            throw std::runtime_error(where +
                                     ": the standard deviations must be two "
                                     "non-negative numbers");
        // map.txt's read counts (reads, contradicted).
        double reads = 0, contradicted = 0;
        if (in >> reads) {
            if (!(in >> contradicted) || !(reads >= 0) || !(contradicted >= 0))
                throw std::runtime_error(where +
                                         ": after the standard deviations, the read "
                                         "counts must be two non-negative numbers");
            r.agreed = uint64_t(std::min(1e15, std::max(1.0, reads - contradicted)));
        }
    }
    std::string extra;
    if (in.clear(), in >> extra)
        throw std::runtime_error(where + ": unexpected '" + extra + "'");
    return r;
}
}  // namespace

void CRFIDTagParticleMap::loadPriorFromTextFile(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot read prior map '" + path + "'");
    std::string line;
    // Fixed seed: the same file gives the same map in every particle's copy.
    rfir::models::TRandom rng(
        CRFIDTagParticleMapImpl::stepSeed(insertionOptions.seed, 0xF11E));
    for (size_t n = 1; std::getline(f, line); n++) {
        std::istringstream k(line);
        std::string kind;
        if (!(k >> kind) || kind[0] == '#') continue;
        if (kind != "tag" && kind != "landmark") continue;  // e.g. emitter records
        const auto r = parseRecord(line, path + ":" + std::to_string(n));
        auto& table = kind == "tag" ? m_tags : m_landmarks;
        if (table.count(r.id))
            throw std::runtime_error(path + ":" + std::to_string(n) + ": " + kind + " '" +
                                     r.id + "' given twice");
        TTagEntry e;
        e.id = r.id;
        e.estimator = CRFIDTagParticleMapImpl::makeEstimator(insertionOptions);
        std::vector<mrpt::math::TPoint2D> pts(insertionOptions.params.numParticles);
        for (auto& p : pts)
            p = {r.x + r.sx * rng.drawGaussian1D_normalized(),
                 r.y + r.sy * rng.drawGaussian1D_normalized()};
        e.estimator->initFromPoints(pts);
        // Seen once: a prior entry is a known landmark, not a first visit.
        e.visits = 1;
        // reseat_contradicted weighs a prior tag by its reads in the file; a
        // surveyed one (no counts) is never placed again by reads.
        e.support = r.agreed.value_or(uint64_t(1) << 62);
        CRFIDTagParticleMapImpl::refresh(*this, e);
        table.emplace(r.id, std::move(e));
    }
}
