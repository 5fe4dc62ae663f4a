# Installs the build tree into a fresh prefix with ./build.sh install, builds Examples/ as an outside project against
# it with find_package(Penumbra), runs the result, and imports the installed Python package.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPYTHON=... -P TestInstalledPackage.cmake
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output
    ERROR_VARIABLE output)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${output}")
  endif ()
  set(last_output "${output}" PARENT_SCOPE)
endfunction ()

# As a user installs: ./build.sh install (its package check and build find nothing to do
# in a tree the test command has built).
run("${CMAKE_COMMAND}" -E env "BUILD_DIR=${BUILD_DIR}" "PREFIX=${prefix}" "JOBS=2"
  "${SOURCE_DIR}/build.sh" install)
foreach (installed IN ITEMS lib/cmake/penumbra/PenumbraConfig.cmake include/penumbra/vtkSoftShadowPass.h
    lib/python3/dist-packages/penumbra/__init__.py lib/python3/dist-packages/penumbra/shadows.py)
  if (NOT EXISTS "${prefix}/${installed}")
    message(FATAL_ERROR "not installed: ${installed}")
  endif ()
endforeach ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples" -B "${WORK_DIR}/examples"
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/examples" -j 2)
# The demo linked against the installed libraries, not the build tree's.
run(ldd "${WORK_DIR}/examples/PenumbraDemo")
string(FIND "${last_output}" "${prefix}/lib/libvtkPenumbraRendering" found)
if (found EQUAL -1)
  message(FATAL_ERROR "PenumbraDemo does not load the installed library:\n${last_output}")
endif ()
run("${WORK_DIR}/examples/PenumbraDemo" --help)
# An application using only the pass loads neither the ray tracer nor Embree.
run(ldd "${WORK_DIR}/examples/MinimalShadows")
string(FIND "${last_output}" "${prefix}/lib/libvtkPenumbraRendering" found)
string(REGEX MATCH "embree|PenumbraRayTracing" truth_library "${last_output}")
if (found EQUAL -1 OR truth_library)
  message(FATAL_ERROR "MinimalShadows should load the installed pass and no ray tracer:\n"
    "${last_output}")
endif ()
run("${WORK_DIR}/examples/MinimalShadows" --no-render)

# Python: the installed package, found through the .pth the install wrote into the
# interpreter's site directory for this prefix (what /usr/local gets).
execute_process(COMMAND "${PYTHON}" -c
  "import sys; print('lib/python%d.%d/dist-packages' % sys.version_info[:2])"
  OUTPUT_VARIABLE site OUTPUT_STRIP_TRAILING_WHITESPACE)
if (NOT EXISTS "${prefix}/${site}/penumbra.pth")
  message(FATAL_ERROR "no ${prefix}/${site}/penumbra.pth")
endif ()
run("${PYTHON}" -c "import site; site.addsitedir('${prefix}/${site}'); import penumbra; p = penumbra.__file__; assert p.startswith('${prefix}/'), p; print(p, penumbra.vtkSoftShadowPass, penumbra.vtkRayTracedVisibility, penumbra.enable_shadows)")
message(STATUS "installed package works: ${last_output}")
