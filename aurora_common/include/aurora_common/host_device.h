// Marks functions callable from both host and CUDA device code.
// Empty outside nvcc, so the same header serves the ROS nodes, the CPU sweep
// and the CUDA kernel (docs/architecture.md, "The one idea").
#pragma once

#if defined(__CUDACC__)
#define AURORA_HD __host__ __device__
#else
#define AURORA_HD
#endif
