// Checks that the package compiling this was built without floating-point
// contraction (-ffp-contract=off), on which the bit-for-bit agreement of the
// ROS loop, the runners and the sweep rests (docs/model.md, "Rounding").
// Compile the including test source with FMA available (-mfma): contraction,
// if allowed, then turns a*b + c into one fused operation.
#pragma once

namespace aurora_common {

// a*b + c with (1 + 2^-30)^2 - (1 + 2^-29): 0 when the product is rounded
// first (as the model expects), 2^-60 when fused.
inline double contractionProbe() {
  static volatile double a = 1.0 + 1.0 / 1073741824.0, b = a, c = -(1.0 + 1.0 / 536870912.0);  // 2^-30, 2^-29
  const double x = a, y = b, z = c;
  return x * y + z;
}

}  // namespace aurora_common
