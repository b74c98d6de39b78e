# Installation and the CMake package: after `cmake --install build --prefix P`, another
# project finds the library with find_package(skylit 0.2) (CMAKE_PREFIX_PATH=P) and links
# skylit::skylit. tests/package/ builds and runs such a project (ctest: package_round_trip).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SKYLIT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/skylit)

install(TARGETS skylit skylit_cli EXPORT skylitTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})

# Public headers. The rule: every header below src/skylit is public and installed,
# except the internal ones listed here. A header is internal if it exists only for
# the library's own .cpp files (and the tests, which see the source tree): it includes
# a private dependency's header (nlohmann, Embree, tinyobjloader, tinygltf, OpenEXR,
# libpng) or is a step of an implementation. No installed header may include an
# internal one or a private dependency's header; the package_round_trip test checks
# both on the installed tree, so a header added to this list too late fails there.
set(SKYLIT_INTERNAL_HEADERS
  core/embedded_data.h         # the data tables as compiled in; spectrum/tabulated.h reads them
  core/text_file.h             # file reading for the readers of photometric and spectral files
  io/image/image_encoders.h    # "Internal to io/": the per-format encoders behind write_image
  io/scene/json_reader.h       # includes <nlohmann/json.hpp>
  io/scene/scene_overrides.h   # takes nlohmann::json; users give overrides to load_scene
  io/scene/scene_parts.h       # includes json_reader.h
  lights/number_text.h         # number parsing for the IES and EULUMDAT readers
  sun/spa_steps.h              # the SPA's intermediate steps; sun/solar_position.h is the interface
)
file(GLOB_RECURSE _skylit_headers RELATIVE ${PROJECT_SOURCE_DIR}/src/skylit
  CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/skylit/*.h)
foreach(_internal IN LISTS SKYLIT_INTERNAL_HEADERS)
  if(NOT EXISTS ${PROJECT_SOURCE_DIR}/src/skylit/${_internal})
    message(FATAL_ERROR "cmake/Install.cmake: internal header ${_internal} does not exist; update the list")
  endif()
endforeach()
list(REMOVE_ITEM _skylit_headers ${SKYLIT_INTERNAL_HEADERS})
foreach(_header IN LISTS _skylit_headers)
  get_filename_component(_dir ${_header} DIRECTORY)
  install(FILES src/skylit/${_header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/skylit/${_dir})
endforeach()

install(EXPORT skylitTargets NAMESPACE skylit:: DESTINATION ${SKYLIT_INSTALL_CMAKEDIR})

# SameMajorVersion: a request for 0.2 accepts any later 0.x but not 1.0. AnyNewerVersion
# would promise that 1.0 and later still serve code written for 0.2, which we do not;
# within 0.x the API may still change between minor versions (semver), which the
# stricter SameMinorVersion would encode, at the cost of refusing 0.3 to code that
# usually still builds.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/skylitConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/skylitConfig.cmake.in
  ${PROJECT_BINARY_DIR}/skylitConfig.cmake
  INSTALL_DESTINATION ${SKYLIT_INSTALL_CMAKEDIR})
install(FILES ${PROJECT_BINARY_DIR}/skylitConfig.cmake ${PROJECT_BINARY_DIR}/skylitConfigVersion.cmake
  DESTINATION ${SKYLIT_INSTALL_CMAKEDIR})

# The round trip: install into a temporary prefix, build and run tests/package against it.
if(SKYLIT_BUILD_TESTS)
  add_test(NAME package_round_trip
    COMMAND ${CMAKE_COMMAND}
      -DBUILD_DIR=${PROJECT_BINARY_DIR}
      -DSOURCE_DIR=${PROJECT_SOURCE_DIR}/tests/package
      -DWORK_DIR=${PROJECT_BINARY_DIR}/package_round_trip
      -DCONFIG=$<CONFIG>
      -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
      -DCXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
      -P ${PROJECT_SOURCE_DIR}/tests/package/round_trip.cmake)
  # It builds a project with -j2: count it as two processors for `ctest -j`.
  set_tests_properties(package_round_trip PROPERTIES LABELS package PROCESSORS 2 TIMEOUT 600)
endif()
