/* rfir: the random generator type every model, filter and simulator draws
 * from. One generator per run is owned by its engine and passed down by
 * reference; code takes a `TRandom&`, never a global. */
#pragma once

#include <mrpt/random/RandomGenerators.h>

namespace rfir::models {
using TRandom = mrpt::random::CRandomGenerator;
}  // namespace rfir::models
