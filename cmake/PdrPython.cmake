# The Python module `pdr` (python/, issue #12): whether to build it, and how.
#
# PDR_PYTHON is ON, OFF or AUTO (the default): AUTO builds the module when pybind11 and the
# Python 3 headers are found, except in a sanitizer or fuzz build, whose instrumented
# libraries would not load into an uninstrumented interpreter (ON there is an error).
# Sets pdr_build_python. When it is set, every library is compiled position-independent,
# since the static libraries are linked into the shared module.
#
# The interpreter: Debian's /usr/bin/python3 when it exists, since the module's test
# dependencies (numpy, pytest) are Debian packages and a python3 that comes first on PATH
# (pyenv's, a virtualenv's) may lack them; -DPython3_EXECUTABLE=... picks another.
# PDR_PYTHON_INSTALL_DIR (relative to the install prefix) is where `cmake --install` puts
# the module: lib/python3.X/ and the last folder of the interpreter's own site-packages
# path (dist-packages on Debian), so that the default prefix /usr/local is on sys.path.
set(PDR_PYTHON AUTO CACHE STRING
  "Build the Python module pdr: ON, OFF, or AUTO (when pybind11 and the Python headers are found)")
set(pdr_build_python OFF)

if(PDR_SANITIZE OR PDR_FUZZ)
  if(PDR_PYTHON AND NOT PDR_PYTHON STREQUAL "AUTO")
    message(FATAL_ERROR "PDR_PYTHON=ON cannot be combined with PDR_SANITIZE or PDR_FUZZ: "
                        "an instrumented module does not load into python3")
  endif()
elseif(PDR_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The interpreter of the module pdr")
  endif()
  if(PDR_PYTHON STREQUAL "AUTO")
    find_package(Python3 3.8 QUIET COMPONENTS Interpreter Development.Module)
    if(Python3_FOUND)
      find_package(pybind11 2.6 CONFIG QUIET)
    endif()
    if(Python3_FOUND AND pybind11_FOUND)
      set(pdr_build_python ON)
    else()
      message(STATUS "pdr: Python module off (needs pybind11-dev and python3-dev)")
    endif()
  else()
    find_package(Python3 3.8 REQUIRED COMPONENTS Interpreter Development.Module)
    find_package(pybind11 2.6 CONFIG REQUIRED)
    set(pdr_build_python ON)
  endif()
endif()

if(pdr_build_python)
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  get_filename_component(pdr_site_folder "${Python3_SITEARCH}" NAME)
  set(PDR_PYTHON_INSTALL_DIR
    "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/${pdr_site_folder}"
    CACHE STRING "Where cmake --install puts the Python module pdr (relative to the prefix)")
  message(STATUS "pdr: Python module for ${Python3_EXECUTABLE}, installed to "
                 "<prefix>/${PDR_PYTHON_INSTALL_DIR}")
endif()
