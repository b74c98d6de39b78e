# The package round trip (ctest: package_round_trip), run with cmake -P:
#   1. install the build tree into WORK_DIR/prefix;
#   2. check the installed headers: each `#include "..."` or <skylit/...> names an
#      installed header, and none includes a private dependency's header;
#   3. configure and build tests/package (find_package(skylit 0.2), skylit::skylit)
#      against that prefix, with a translation unit that includes every installed header;
#   4. run its program, which renders a small scene and checks the image.
# Any failure is a FATAL_ERROR, so the test fails.
# Inputs: BUILD_DIR, SOURCE_DIR (this folder), WORK_DIR, CONFIG, CXX_COMPILER,
#         CXX_COMPILER_LAUNCHER (may be empty).
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "round_trip.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}):\n${out}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install.
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

# 2. The installed headers.
set(include_dir ${prefix}/include)
file(GLOB_RECURSE headers RELATIVE ${include_dir} ${include_dir}/*.h ${include_dir}/*.hpp)
list(LENGTH headers header_count)
if(header_count LESS 10)
  message(FATAL_ERROR "only ${header_count} headers installed under ${include_dir}")
endif()
# Headers of the library's private dependencies: nlohmann-json, Embree, tinyobjloader,
# tinygltf, OpenEXR/Imath, libpng (and its zlib).
set(private_include_regex
  "^(nlohmann/|embree[0-9]*/|tiny_obj_loader|tiny_gltf|json\\.hpp|OpenEXR/|Imath/|Imf|Iex|half\\.h|png\\.h|pngconf\\.h|zlib\\.h)")
set(problems "")
set(all_headers_cpp "// Written by tests/package/round_trip.cmake: every installed header.\n")
foreach(header IN LISTS headers)
  string(APPEND all_headers_cpp "#include \"${header}\"\n")
  get_filename_component(header_dir ${include_dir}/${header} DIRECTORY)
  file(STRINGS ${include_dir}/${header} include_lines REGEX "^[ \t]*#[ \t]*include")
  foreach(line IN LISTS include_lines)
    if(line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
      set(name ${CMAKE_MATCH_1})
      if(NOT EXISTS ${include_dir}/${name} AND NOT EXISTS ${header_dir}/${name})
        string(APPEND problems "  ${header} includes \"${name}\", which is not installed\n")
      endif()
    elseif(line MATCHES "#[ \t]*include[ \t]*<([^>]+)>")
      set(name ${CMAKE_MATCH_1})
      if(name MATCHES "^skylit/" AND NOT EXISTS ${include_dir}/${name})
        string(APPEND problems "  ${header} includes <${name}>, which is not installed\n")
      elseif(name MATCHES "${private_include_regex}")
        string(APPEND problems "  ${header} includes <${name}>, a private dependency's header\n")
      endif()
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "installed headers under ${include_dir}:\n${problems}")
endif()
file(WRITE ${WORK_DIR}/all_headers.cpp "${all_headers_cpp}")

# 3. A project that uses the package.
set(configure_args
  -S ${SOURCE_DIR} -B ${WORK_DIR}/build
  -DCMAKE_BUILD_TYPE=${CONFIG}
  -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DSKYLIT_EXPECTED_PREFIX=${prefix}
  -DSKYLIT_ALL_HEADERS_CPP=${WORK_DIR}/all_headers.cpp)
if(CXX_COMPILER_LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER})
endif()
run("configuring tests/package" ${CMAKE_COMMAND} ${configure_args})
run("building tests/package" ${CMAKE_COMMAND} --build ${WORK_DIR}/build --config ${CONFIG} -j2)

# 4. Run it.
find_program(app NAMES app PATHS ${WORK_DIR}/build ${WORK_DIR}/build/${CONFIG} NO_DEFAULT_PATH REQUIRED)
run("the package's user program" ${app})
message(STATUS "package round trip: ${header_count} headers checked; ${last_output}")
