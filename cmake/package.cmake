# The installable package: libcurdle.so (the application layer and everything under it, one
# versioned shared library), its public headers, and curdleConfig.cmake with curdle::curdle.
include(CMakePackageConfigHelpers)

# The application's headers a program calls (a run from recipe text and overrides, its report,
# layout and outputs' bytes; search, measure and fit) and every header they include.
set(CURDLE_PUBLIC_HEADERS
  src/app/chain_reading.h src/app/fit_run.h src/app/generated_run.h src/app/measure_run.h src/app/observer.h
  src/app/output_sink.h src/app/outputs.h src/app/reproduce.h src/app/run.h src/app/search_run.h
  src/app/stopping.h src/app/version.h
  src/curdle/bitset.h src/curdle/box.h src/curdle/chain_fit.h src/curdle/state_tree.h src/curdle/check.h src/curdle/boxcount.h src/curdle/cell_index.h
  src/curdle/curd.h src/curdle/curdling.h src/curdle/density.h src/curdle/error.h src/curdle/fit.h
  src/curdle/lattice.h src/curdle/markov.h src/curdle/markov_report.h src/curdle/measure.h
  src/curdle/overlay.h src/curdle/probability.h
  src/curdle/report.h src/curdle/search.h src/curdle/stop.h
  src/layout/block_views.h src/layout/drawing_sheet.h src/layout/element_id.h
  src/layout/envelope_frames.h src/layout/fabrication_sheets.h src/layout/geometry.h
  src/layout/installer_sheets.h
  src/layout/layout.h src/layout/layout_kind.h src/layout/piece_rows.h src/layout/planting_spec.h
  src/layout/surface_frame.h src/layout/wkt.h
  src/io/atomic_file.h src/io/image.h
  src/recipe/recipe.h src/recipe/recipe_files.h
  export/report/measure_files.h export/report/report_json.h export/schedules/schedule.h)

add_library(curdle_library SHARED src/app/version.cpp)
add_library(curdle::curdle ALIAS curdle_library)
target_compile_definitions(curdle_library PRIVATE CURDLE_VERSION="${PROJECT_VERSION}")
# Every object of the layers, so that the library holds what its headers declare. (CMake's
# WHOLE_ARCHIVE feature refuses libraries that also come in as another's dependency.)
target_link_libraries(curdle_library
  PRIVATE -Wl,--whole-archive curdle_app curdle_export curdle_recipe curdle_site curdle_building curdle_io curdle_layout curdle_core
          -Wl,--no-whole-archive curdle_warnings
  PUBLIC nlohmann_json::nlohmann_json)
target_include_directories(curdle_library PUBLIC
  "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src;${PROJECT_SOURCE_DIR}>"
  "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/curdle>")
target_compile_features(curdle_library INTERFACE cxx_std_20)
set_target_properties(curdle_library PROPERTIES
  OUTPUT_NAME curdle EXPORT_NAME curdle
  VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})

install(TARGETS curdle_library EXPORT curdleTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/curdle)
foreach(header ${CURDLE_PUBLIC_HEADERS})
  string(REGEX REPLACE "^src/" "" relative ${header})
  get_filename_component(dir ${relative} DIRECTORY)
  install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/curdle/${dir})
endforeach()

set(CURDLE_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/curdle)
install(FILES LICENSE THIRD-PARTY-NOTICES DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(EXPORT curdleTargets NAMESPACE curdle:: DESTINATION ${CURDLE_PACKAGE_DIR})
configure_package_config_file(cmake/curdleConfig.cmake.in
  ${CMAKE_BINARY_DIR}/curdleConfig.cmake INSTALL_DESTINATION ${CURDLE_PACKAGE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/curdleConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/curdleConfig.cmake ${CMAKE_BINARY_DIR}/curdleConfigVersion.cmake
  DESTINATION ${CURDLE_PACKAGE_DIR})

# The Python module: curdle/__init__.py and the native curdle._curdle over libcurdle.so, in the
# build tree's python/ (PYTHONPATH=build/release/python) and installed into the prefix's
# lib/python3.X/site-packages. Debian's Python, which Debian's Blender runs too.
option(CURDLE_PYTHON "Build the Python module (pybind11)" ON)
if(CURDLE_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module)
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 REQUIRED CONFIG)
  set(CURDLE_PYTHON_DIR ${CMAKE_BINARY_DIR}/python)
  pybind11_add_module(curdle_python MODULE NO_EXTRAS src/python/module.cpp
                      src/python/interruptible.cpp)
  target_link_libraries(curdle_python PRIVATE curdle_library curdle_warnings)
  set(CURDLE_SITE_PACKAGES
      lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/site-packages)
  # Installed, the module finds libcurdle.so relative to itself, wherever the prefix is.
  file(RELATIVE_PATH module_to_library /prefix/${CURDLE_SITE_PACKAGES}/curdle
       /prefix/${CMAKE_INSTALL_LIBDIR})
  set_target_properties(curdle_python PROPERTIES
    OUTPUT_NAME _curdle LIBRARY_OUTPUT_DIRECTORY ${CURDLE_PYTHON_DIR}/curdle
    CXX_VISIBILITY_PRESET hidden
    INSTALL_RPATH "$ORIGIN/${module_to_library}")
  # The package's Python beside the module, copied again whenever it changes.
  # py.typed: the package's annotations are its types (PEP 561).
  # _curdle.pyi: the native module's types, for type checkers and stubtest.
  set(python_files __init__.py py.typed _curdle.pyi)
  list(TRANSFORM python_files PREPEND ${PROJECT_SOURCE_DIR}/src/python/curdle/ OUTPUT_VARIABLE python_sources)
  list(TRANSFORM python_files PREPEND ${CURDLE_PYTHON_DIR}/curdle/ OUTPUT_VARIABLE python_copies)
  add_custom_command(OUTPUT ${python_copies}
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${python_sources} ${CURDLE_PYTHON_DIR}/curdle/
    DEPENDS ${python_sources})
  add_custom_target(curdle_python_files DEPENDS ${python_copies})
  add_dependencies(curdle_python curdle_python_files)
  install(TARGETS curdle_python LIBRARY DESTINATION ${CURDLE_SITE_PACKAGES}/curdle)
  install(FILES src/python/curdle/__init__.py src/python/curdle/py.typed
                src/python/curdle/_curdle.pyi
          DESTINATION ${CURDLE_SITE_PACKAGES}/curdle)
endif()
