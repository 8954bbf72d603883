// A found segment (a fold, a grainline) against the truth, shared by the vision and the window tests:
// how far its ends lie from the truth's ends, the way round that fits, since a finder may give a
// segment's ends in either order.
#pragma once

#include "geometry/bezier.h"

#include <algorithm>

namespace kontur::test {

// The larger of the two ends' distances from the truth's, for the pairing of ends that makes it least.
inline double endsOff(const geo::Point &foundA, const geo::Point &foundB, const geo::Point &truthA,
                      const geo::Point &truthB)
{
    return std::min(std::max((foundA - truthA).norm(), (foundB - truthB).norm()),
                    std::max((foundA - truthB).norm(), (foundB - truthA).norm()));
}

} // namespace kontur::test
