// tinyexr's implementation, compiled into Windows builds (Debian ships
// tinyexr for Linux only as a shared library; see cmake/CrossDependencies.cmake).
// zlib comes from the target toolchain; no threads or OpenMP, as in Debian's build.
#define TINYEXR_IMPLEMENTATION
#define TINYEXR_USE_MINIZ 0
#define TINYEXR_USE_THREAD 0
#define TINYEXR_USE_OPENMP 0
#include <tinyexr.h>
#include <zlib.h>
