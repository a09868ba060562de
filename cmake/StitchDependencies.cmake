# The core library's dependencies; the optional parts find their own where they are built.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(TBB REQUIRED)
find_package(fmt REQUIRED)
# NLopt: unfold_tubes' descent (Debian: libnlopt-cxx-dev, whose nlopt.hpp is header-only over
# the C library).
find_package(NLopt CONFIG REQUIRED)
include(StitchOpenSubdiv)
