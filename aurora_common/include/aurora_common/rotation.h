// The body-to-world rotation R = Rz(psi) Ry(theta) Rx(phi) (Tait-Bryan; docs/model.md,
// "State, command, frames"), written once for the model, the controllers
// and the batch engines; from the sines and cosines the caller already has.
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_common {

template <typename T>
AURORA_HD inline void rotationMatrix(const T& sphi, const T& cphi, const T& sth, const T& cth,
                                     const T& spsi, const T& cpsi, T R[3][3]) {
  R[0][0] = cpsi * cth;
  R[0][1] = cpsi * sth * sphi - spsi * cphi;
  R[0][2] = cpsi * sth * cphi + spsi * sphi;
  R[1][0] = spsi * cth;
  R[1][1] = spsi * sth * sphi + cpsi * cphi;
  R[1][2] = spsi * sth * cphi - cpsi * sphi;
  R[2][0] = -sth;
  R[2][1] = cth * sphi;
  R[2][2] = cth * cphi;
}

}  // namespace aurora_common
