# Reads the firmware's compiler flags from platformio.ini, so that the CMake
# build of the firmware and the PlatformIO build users flash with cannot
# drift apart: one list of flags, in the file PlatformIO reads.
#
#   strider_platformio_build_flags(<ini> <out-var>)
#
# <out-var> gets the [env] section's build_flags as a list: continuation
# lines (indented) joined, `;` comments dropped, `-D NAME` joined to
# `-DNAME`. Only what this project's platformio.ini uses is understood: no
# ${...} interpolation, no per-environment build_flags (a FATAL_ERROR says
# so, rather than a silent difference).
function(strider_platformio_build_flags ini out_var)
  # A changed platformio.ini configures the build again (its flags with it).
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ini})
  file(STRINGS ${ini} lines)
  set(section "")
  set(in_flags OFF)
  set(text "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^\\[([^]]+)\\]")
      set(section "${CMAKE_MATCH_1}")
      set(in_flags OFF)
      continue()
    endif()
    if(line MATCHES "^[ \t]*;" OR line MATCHES "^[ \t]*$")
      continue()  # a comment or a blank line (also inside a continued value)
    endif()
    if(line MATCHES "^build_flags[ \t]*=(.*)$")
      if(NOT section STREQUAL "env")
        message(FATAL_ERROR "${ini}: build_flags in [${section}]: only [env]'s are read into the CMake firmware build")
      endif()
      set(in_flags ON)
    elseif(NOT (in_flags AND line MATCHES "^[ \t]+(.*)$"))
      set(in_flags OFF)
      continue()
    endif()
    string(REGEX REPLACE "[ \t]+;.*$" "" value "${CMAKE_MATCH_1}")  # an inline comment
    string(APPEND text " ${value}")
  endforeach()
  if(text MATCHES "\\$\\{")
    message(FATAL_ERROR "${ini}: build_flags with \${...} interpolation are not understood here")
  endif()
  string(REGEX REPLACE "-D[ \t]+" "-D" text "${text}")
  string(STRIP "${text}" text)
  separate_arguments(flags UNIX_COMMAND "${text}")
  set(${out_var} ${flags} PARENT_SCOPE)
endfunction()
