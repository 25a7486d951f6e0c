# All dependencies come from Debian packages (scripts/install-deps.sh).
# Nothing is downloaded at build time.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(fmt REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PNG REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Ceres REQUIRED)
# CGAL 5.5 (header-only): straight skeleton, constrained Delaunay, convex partition.
find_package(CGAL REQUIRED)
# CMake's own FindBullet: Debian's BulletConfig.cmake is broken (relative paths).
find_package(Bullet REQUIRED MODULE)
# Bullet in double precision (-DBT_USE_DOUBLE_PRECISION and the -float64 libraries):
# the rigid-body reference (validation/bullet) uses it; never mix the two builds in one target.
pkg_check_modules(BULLET_FLOAT64 REQUIRED IMPORTED_TARGET bullet-float64)
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
# OSMesa alone: linking libGL before it makes glGetString return NULL.
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
find_package(MPI COMPONENTS C)
# Embree 3 (libembree-dev): the snow model's ray-cast baseline.
find_package(embree 3 REQUIRED)

find_program(LIGGGHTS_EXECUTABLE liggghts)
if(NOT LIGGGHTS_EXECUTABLE)
  message(WARNING "liggghts not found: reference runs will fail until scripts/install-deps.sh installs it")
endif()
find_program(REPOSE_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
