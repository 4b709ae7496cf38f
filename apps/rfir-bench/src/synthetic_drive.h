/* rfir-bench: the synthetic drive that builds an N-tag state with the method
 * itself, then the timed updates in which two known tags are read.
 *
 * The robot (8 readers of 60 mm on the simulator's default ring) drives along
 * +x. Population: each insertion step moves 0.1 m and reads up to 64 new tags
 * (8 per reader, at the reader's centre); the next step moves 5 mm and re-reads
 * two of them, so the particles are weighed and resampled as in a real run.
 * Timed updates: the robot jitters by +-5 mm over the last insertion spot and
 * two readers read one known tag each; the four reader pairs take turns, so
 * every read starts a new visit of its tag (all tag-map policies weigh the
 * robot with it). */
#pragma once

#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/slam/slam_engine.h>

#include <cstddef>
#include <vector>

namespace rfir::bench
{
class CSyntheticDrive
{
public:
    explicit CSyntheticDrive(size_t N, size_t tagsPerStep = 64);

    size_t populationSteps() const { return 2 * chunkStart_.size(); }
    rfir::slam::TSlamInput populationStep(size_t i) const;
    /** Timed update k (k = 0, 1, ...), after every population step. */
    rfir::slam::TSlamInput timedStep(size_t k) const;
    /** Detections in a timed update. */
    static constexpr size_t kTimedDetections = 2;

private:
    rfir::obs::CObservationRFIDReaders::Ptr observation(
        const std::vector<std::pair<size_t, size_t>>& readerTag) const;

    size_t N_;
    std::vector<size_t> chunkStart_;  //!< first tag index of each insertion step
    std::vector<rfir::obs::TRFIDReader> readers_;
};

std::string syntheticTagId(size_t i);

}  // namespace rfir::bench
