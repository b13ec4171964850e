# The page's own files (web/*.html, *.js, *.css), without web/node_modules or the npm files.
# Usage: cmake -DFROM=.../web -DTO=.../share/curdle/web -P copy_page.cmake
file(GLOB files RELATIVE "${FROM}" "${FROM}/*.html" "${FROM}/*.js" "${FROM}/*.css")
file(MAKE_DIRECTORY "${TO}")
foreach(f ${files})
  file(COPY_FILE "${FROM}/${f}" "${TO}/${f}" ONLY_IF_DIFFERENT)
endforeach()
