#pragma once
// The DEM's per-contact kernels are compiled three times (x86-64-v4, v3 and the baseline) and
// the best one is chosen when the program starts (GCC's target_clones), with the same bits on
// every machine (-ffp-contract=off, tools/mesowave/CMakeLists.txt). Clang 14, which builds
// only the fuzz targets (make fuzz), takes no "arch=" clones: there the baseline alone.
#if defined(__clang__)
#define MESOWAVE_KERNEL_CLONES
#else
#define MESOWAVE_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
