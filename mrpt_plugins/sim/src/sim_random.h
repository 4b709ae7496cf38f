/* rfir-sim: the generator of the simulated world's truth. It stays MRPT's
 * Mersenne twister (seeded per stream from --seed, never the global one), so
 * that every simulated log, bundled dataset and test world is byte-identical
 * to what it was before the SLAM engines got their own generator
 * (rfir::models::TRandom): a change of the estimators' draws must not also
 * change the data they are tested on. */
#pragma once

#include <mrpt/random/RandomGenerators.h>

namespace rfir::sim {
using TSimRandom = mrpt::random::CRandomGenerator;
}  // namespace rfir::sim
