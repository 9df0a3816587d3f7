// This package compiles the model without FMA contraction (its own
// CMakeLists sets -ffp-contract=off, whatever tool builds it).
#include <gtest/gtest.h>

#include "aurora_common/fp_contract_probe.h"

TEST(FpContract, ModelCompiledWithoutContraction) {
  if (!__builtin_cpu_supports("fma")) GTEST_SKIP() << "this CPU has no FMA: the probe cannot tell";
  EXPECT_EQ(aurora_common::contractionProbe(), 0.0)
      << "a*b + c was fused: -ffp-contract=off is missing from this package's compile options";
}
