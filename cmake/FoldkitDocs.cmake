# API reference: `cmake --build BUILD --target docs` runs Doxygen on the public headers and
# writes BUILD/docs/html/index.html, its warnings to BUILD/docs/doxygen-warnings.txt
# (scripts/check-docs.sh fails when that file is not empty). No target without Doxygen.
find_package(Doxygen QUIET)

if(DOXYGEN_FOUND)
  set(FOLDKIT_DOCS_OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/docs)

  # Each library folder's public headers; folders still being written may not exist yet.
  set(FOLDKIT_DOCS_INPUT "")
  foreach(folder geometry io simulation dynamics analysis folding statespaces planners bench)
    if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/include)
      string(APPEND FOLDKIT_DOCS_INPUT " \"${PROJECT_SOURCE_DIR}/${folder}/include\"")
    endif()
  endforeach()
  string(STRIP "${FOLDKIT_DOCS_INPUT}" FOLDKIT_DOCS_INPUT)

  configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${FOLDKIT_DOCS_OUTPUT}/Doxyfile @ONLY)

  # Doxygen rewrites the warning log on every run, so it holds only the last run's warnings.
  add_custom_target(docs
    COMMAND Doxygen::doxygen ${FOLDKIT_DOCS_OUTPUT}/Doxyfile
    WORKING_DIRECTORY ${FOLDKIT_DOCS_OUTPUT}
    COMMENT "API reference (Doxygen) in ${FOLDKIT_DOCS_OUTPUT}/html"
    VERBATIM)
else()
  message(STATUS "Doxygen not found: no 'docs' target")
endif()
