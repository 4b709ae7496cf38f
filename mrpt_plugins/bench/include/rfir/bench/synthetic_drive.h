/* rfir-bench: the synthetic drive that builds an N-tag state with the method
 * itself, then the timed updates in which two known tags are read.
 *
 * The robot (the simulator's default ring of 8 readers of 60 mm) jitters by
 * +-5 mm about one spot, so the robot filter stays consistent however many
 * steps the build takes (a drive without loop closures would drift and trip
 * the kidnap monitor). Population step i reads up to 64 new tags (8 per
 * reader, at the reader's centre) and re-reads two tags first read at step
 * i - 2: a new visit, so the robot is weighed and resampled as in a real run,
 * and FastSLAM's particles come to share the EKFs of common ancestors.
 * Timed updates: two readers read one known tag each; the four reader pairs
 * take turns, so every read starts a new visit of its tag (every tag-map
 * policy weighs the robot with it). */
#pragma once

#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/slam/slam_engine.h>

#include <cstddef>
#include <vector>

namespace rfir::bench {
class CSyntheticDrive {
  public:
    explicit CSyntheticDrive(size_t N, size_t tagsPerStep = 64);

    size_t populationSteps() const { return chunkStart_.size(); }
    rfir::slam::TSlamInput populationStep(size_t i) const;
    /** Timed update k (k = 0, 1, ...), after every population step. */
    rfir::slam::TSlamInput timedStep(size_t k) const;

  private:
    rfir::obs::CObservationRFIDReaders::Ptr observation(
        const std::vector<std::pair<size_t, size_t>>& readerTag) const;

    size_t N_;
    std::vector<size_t> chunkStart_;  //!< first tag index of each insertion step
    std::vector<rfir::obs::TRFIDReader> readers_;
};

}  // namespace rfir::bench
