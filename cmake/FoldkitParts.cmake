# What this configuration builds, said once at the end of every configure (issue 32): each part
# that can be left out registers here whether it is built and, if not, why and which Debian
# packages bring it. A part left out is never silent:
# - the summary lists it with its reason;
# - FOLDKIT_REQUIRE_ALL_PARTS=ON (scripts/build.sh and so scripts/test.sh, which promise every
#   part) turns any part left out into a configure error, so the test command cannot quietly run
#   a smaller suite than the README promises.
option(FOLDKIT_REQUIRE_ALL_PARTS "Fail the configure when any optional part (Python, browser app, its tests, …) is left out" OFF)

# Records one part: foldkit_part(NAME BUILT [WHY]). NAME: what a user calls it; BUILT: a boolean;
# WHY: why it is left out and what brings it (ignored when built).
function(foldkit_part name built)
  if(built)
    set(line "built")
  else()
    set(line "NOT built: ${ARGN}")
    set_property(GLOBAL APPEND PROPERTY FOLDKIT_PARTS_MISSING "${name}")
  endif()
  set_property(GLOBAL APPEND PROPERTY FOLDKIT_PARTS_SUMMARY "${name}|${line}")
endfunction()

# Prints the summary; fails when FOLDKIT_REQUIRE_ALL_PARTS is on and a part is left out.
function(foldkit_parts_summary)
  get_property(lines GLOBAL PROPERTY FOLDKIT_PARTS_SUMMARY)
  get_property(missing GLOBAL PROPERTY FOLDKIT_PARTS_MISSING)
  set(text "foldkit parts of this build (${CMAKE_BINARY_DIR}):")
  foreach(entry ${lines})
    string(FIND "${entry}" "|" bar)
    string(SUBSTRING "${entry}" 0 ${bar} name)
    math(EXPR after "${bar} + 1")
    string(SUBSTRING "${entry}" ${after} -1 line)
    string(LENGTH "${name}" width)
    set(pad "")
    if(width LESS 26)
      math(EXPR count "26 - ${width}")
      string(REPEAT "." ${count} pad)
    endif()
    string(APPEND text "\n  ${name} ${pad} ${line}")
  endforeach()
  if(missing AND FOLDKIT_REQUIRE_ALL_PARTS)
    string(REPLACE ";" ", " names "${missing}")
    message(FATAL_ERROR "${text}\nFOLDKIT_REQUIRE_ALL_PARTS is on (scripts/build.sh, scripts/test.sh) and these parts "
                        "are left out: ${names}. Install what each line names (bash scripts/install-deps.sh) and configure again.")
  endif()
  message(STATUS "${text}")
endfunction()
