# The part of three.js the page's 3-D view loads (npm, a dependency of the page itself:
# web/package.json, installed by setup.sh): the module build, the glTF loader with the
# utilities it imports, the orbit controls and the licence. Without it the page still works
# and says the 3-D view is missing.
# Usage: cmake -DFROM=.../node_modules/three -DTO=.../web/vendor/three -P copy_three.cmake
set(files
  build/three.module.js
  build/three.core.js
  examples/jsm/loaders/GLTFLoader.js
  examples/jsm/utils/BufferGeometryUtils.js
  examples/jsm/utils/SkeletonUtils.js
  examples/jsm/controls/OrbitControls.js
  LICENSE)
if(NOT EXISTS "${FROM}/build/three.module.js")
  message(STATUS "three.js not found in ${FROM}: run setup.sh for the page's 3-D view")
  return()
endif()
foreach(f ${files})
  get_filename_component(dir "${TO}/${f}" DIRECTORY)
  file(MAKE_DIRECTORY "${dir}")
  file(COPY_FILE "${FROM}/${f}" "${TO}/${f}" ONLY_IF_DIFFERENT)
endforeach()
