# The core library's dependencies; the optional parts find their own where they are built.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(TBB REQUIRED)
find_package(fmt REQUIRED)
include(StitchOpenSubdiv)
