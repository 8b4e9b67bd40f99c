# test_areas_registered (tests/areas_registered.sh): each test area this build should have, from
# what it found, must be registered with ctest, so an area cannot drop out silently; an area
# configured out (or whose tools were not found) is listed in the test's output and at
# configure time. Included last from the top-level CMakeLists.txt, when every area is known.
set(areas)
set(left_out)

# Fuzz: libFuzzer needs clang (tests/server/fuzz). The same cached lookup as there.
find_program(GRAINLAB_CLANGXX NAMES clang++ clang++-14)
if(NOT TARGET grainlab_server)
  list(APPEND left_out "server, fuzz and browser tests: the server is not built (GRAINLAB_BUILD_SERVER=OFF)")
else()
  list(APPEND areas "expect=server=the server is built")
  if(DEFINED GRAINLAB_FUZZ AND NOT GRAINLAB_FUZZ)
    list(APPEND left_out "fuzz tests: configured with -DGRAINLAB_FUZZ=OFF")
  elseif(NOT GRAINLAB_CLANGXX)
    list(APPEND left_out "fuzz tests: no clang++ found (./scripts/setup installs clang)")
  else()
    list(APPEND areas "expect=fuzz=clang++ was found (${GRAINLAB_CLANGXX})")
  endif()
  if(NOT GRAINLAB_BROWSER_TESTS)
    list(APPEND left_out "browser tests: configured with -DGRAINLAB_BROWSER_TESTS=OFF")
  else()
    list(APPEND areas "expect=browser=the server is built and GRAINLAB_BROWSER_TESTS is ON")
  endif()
endif()

# MPI: the sweep under mpirun (tests/studies). Without MPI that test fails on its own.
if(GRAINLAB_HAS_MPI)
  list(APPEND areas "expect=mpi=MPI was found")
endif()

# LAMMPS: the export/import round trip through Debian's lmp (tests/lammps).
if(GRAINLAB_LMP)
  list(APPEND areas "expect=lammps=LAMMPS was found (${GRAINLAB_LMP})")
else()
  list(APPEND left_out "LAMMPS round trip: no lmp found (./scripts/setup installs lammps)")
endif()

# Python: the module's tests (python/, tests/python).
if(NOT GRAINLAB_BUILD_PYTHON)
  list(APPEND left_out "Python tests: configured with -DGRAINLAB_BUILD_PYTHON=OFF")
elseif(NOT TARGET grainlab_python)
  list(APPEND left_out "Python tests: python3-dev or pybind11-dev not found (./scripts/setup installs them)")
else()
  list(APPEND areas "expect=python=the Python module is built")
  if(NOT GRAINLAB_PYTHON_OPTIONAL_MODULES)
    list(APPEND left_out "the Python tests' VTK and pandas parts: configured with -DGRAINLAB_PYTHON_OPTIONAL_MODULES=OFF")
  endif()
endif()

foreach(what ${left_out})
  message(STATUS "Tests left out: ${what}")
endforeach()
list(TRANSFORM left_out PREPEND "left-out=")
add_test(NAME test_areas_registered COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tests/areas_registered.sh
         ${CMAKE_CTEST_COMMAND} ${PROJECT_BINARY_DIR} ${areas} ${left_out})
set_tests_properties(test_areas_registered PROPERTIES LABELS unit TIMEOUT 60)
