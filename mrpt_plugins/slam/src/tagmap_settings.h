/* rfir: the tag map's options as the PF/PS engine and its loaders share
 * them (private to rfir_slam). */
#pragma once

#include <rfir/maps/CRFIDTagParticleMap.h>

namespace rfir::slam {
struct TTagMapSettings {
    rfir::maps::CRFIDTagParticleMap::TInsertionOptions insertion;
    rfir::maps::CRFIDTagParticleMap::TLikelihoodOptions likelihood;
};
}  // namespace rfir::slam
