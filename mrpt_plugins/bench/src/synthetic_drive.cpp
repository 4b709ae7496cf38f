#include <rfir/bench/synthetic_drive.h>

#include <rfir/sim/simulator.h>

#include <cstdio>
#include <stdexcept>

namespace rfir::bench {
namespace {
constexpr double kJitter = 0.005;  //!< m, back and forth at every step
constexpr size_t kReaders = 8;
}  // namespace

namespace {
std::string syntheticTagId(size_t i) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "T%08zu", i);
    return buf;
}
}  // namespace

CSyntheticDrive::CSyntheticDrive(size_t N, size_t perStep) : N_(N) {
    if (N < kReaders)
        throw std::invalid_argument("the synthetic drive needs N >= 8 tags");
    // Every step reads at least 8 new tags (one per reader), and the LAST one
    // is full, so every reader has a tag where the timed updates happen.
    size_t first = N % perStep;
    if (first != 0 && first < kReaders && N > perStep) first += perStep;
    if (first != 0 && N > first) chunkStart_.push_back(0);
    for (size_t s = N > first ? first : 0; s < N; s += perStep) chunkStart_.push_back(s);
    readers_ = rfir::sim::ringReaderLayout(0.15, 0.03);
    if (readers_.size() != kReaders)
        throw std::logic_error("the synthetic drive expects 8 readers");
}

rfir::obs::CObservationRFIDReaders::Ptr CSyntheticDrive::observation(
    const std::vector<std::pair<size_t, size_t>>& readerTag) const {
    auto o = std::make_shared<rfir::obs::CObservationRFIDReaders>();
    o->sensorLabel = "RFID";
    for (const auto& r : readers_) o->readings.push_back({r, {}});
    for (const auto& [r, tag] : readerTag)
        o->readings[r].tags.push_back(syntheticTagId(tag));
    return o;
}

rfir::slam::TSlamInput CSyntheticDrive::populationStep(size_t i) const {
    const size_t begin = chunkStart_.at(i);
    const size_t end = i + 1 < chunkStart_.size() ? chunkStart_[i + 1] : N_;
    rfir::slam::TSlamInput in;
    in.t = 0.1 * double(i);
    if (i > 0)
        in.odometryIncrement = mrpt::poses::CPose2D(i % 2 ? kJitter : -kJitter, 0, 0);
    std::vector<std::pair<size_t, size_t>> reads;
    for (size_t t = begin; t < end; t++) reads.push_back({(t - begin) % kReaders, t});
    if (i >= 2) {
        // A new visit of two tags of step i - 2 (absent from step i - 1).
        const size_t old = chunkStart_[i - 2];
        reads.push_back({0, old});
        reads.push_back({1, old + 1});
    }
    in.rfid = observation(reads);
    return in;
}

rfir::slam::TSlamInput CSyntheticDrive::timedStep(size_t k) const {
    const size_t last = chunkStart_.back();
    const size_t pair = k % (kReaders / 2);
    rfir::slam::TSlamInput in;
    in.t = 0.1 * double(populationSteps() + k);
    const size_t step = populationSteps() + k;
    in.odometryIncrement = mrpt::poses::CPose2D(step % 2 ? kJitter : -kJitter, 0, 0);
    in.rfid =
        observation({{2 * pair, last + 2 * pair}, {2 * pair + 1, last + 2 * pair + 1}});
    return in;
}

}  // namespace rfir::bench
