# StriderAvr.cmake: the AVR side of the host build.
#
# The host project is not cross-compiling: avr-g++ is called directly through
# custom commands and tests, and the simulated Mega (libsimavr) runs the
# resulting ELF files inside host programs. Included by tools/bench and
# test/avr; include it in every directory that needs the variables (they are
# directory-scoped); the probes are cached.
#
# Sets:
#   STRIDER_AVR_CXX        avr-g++ (empty when missing)
#   STRIDER_AVR_SIZE       avr-size
#   STRIDER_AVR_FOUND      avr-g++, avr-size and avr-libc usable
#   STRIDER_SIMAVR_FOUND   libsimavr + libelf usable (imported target strider::simavr)
#   STRIDER_AVR_CXX_FLAGS  flags every AVR compile uses
# Functions:
#   strider_avr_firmware(NAME SOURCES src... [INCLUDES dir...] [DEFINES d...]
#                        [WARNINGS w...] [DEPENDS file...])
#       builds ${CMAKE_CURRENT_BINARY_DIR}/NAME.elf; target NAME; property
#       STRIDER_ELF holds the path.
#   strider_add_header_checks(ROOT dir)
#       one ctest test per public header and compiler (host C++17, avr-g++).

# Functions keep the policies of their definition: depfile paths of the
# firmware's custom command are relative to its binary directory.
if(POLICY CMP0116)
  cmake_policy(SET CMP0116 NEW)
endif()

set(STRIDER_AVR_MCU atmega2560)
set(STRIDER_AVR_F_CPU 16000000)

find_program(STRIDER_AVR_CXX NAMES avr-g++ DOC "avr-g++ for the ATmega2560 builds")
find_program(STRIDER_AVR_SIZE NAMES avr-size DOC "avr-size for flash/RAM figures")

set(STRIDER_AVR_FOUND OFF)
if(STRIDER_AVR_CXX AND STRIDER_AVR_SIZE AND STRIDER_AVR_PROBED STREQUAL STRIDER_AVR_CXX)
  set(STRIDER_AVR_FOUND ON)
elseif(STRIDER_AVR_CXX AND STRIDER_AVR_SIZE)
  # avr-libc is a separate package: check that <avr/io.h> is there.
  file(WRITE ${CMAKE_BINARY_DIR}/strider_avr_probe.cpp "#include <avr/io.h>\nint main() { GPIOR0 = 1; }\n")
  execute_process(
    COMMAND ${STRIDER_AVR_CXX} -mmcu=${STRIDER_AVR_MCU} -fsyntax-only ${CMAKE_BINARY_DIR}/strider_avr_probe.cpp
    RESULT_VARIABLE _avr_rc OUTPUT_QUIET ERROR_VARIABLE _avr_err)
  if(_avr_rc EQUAL 0)
    set(STRIDER_AVR_FOUND ON)
    set(STRIDER_AVR_PROBED ${STRIDER_AVR_CXX} CACHE INTERNAL "avr-g++ that compiled <avr/io.h>")
  else()
    message(STATUS "Strider AVR: avr-g++ cannot compile <avr/io.h> (install avr-libc): ${_avr_err}")
  endif()
endif()

set(STRIDER_SIMAVR_FOUND OFF)
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(STRIDER_PC_SIMAVR QUIET simavr)
endif()
find_path(STRIDER_SIMAVR_INCLUDE sim_avr.h HINTS ${STRIDER_PC_SIMAVR_INCLUDE_DIRS} PATH_SUFFIXES simavr)
find_library(STRIDER_SIMAVR_LIB simavr HINTS ${STRIDER_PC_SIMAVR_LIBRARY_DIRS})
find_library(STRIDER_ELF_LIB elf)
if(STRIDER_SIMAVR_INCLUDE AND STRIDER_SIMAVR_LIB AND STRIDER_ELF_LIB)
  set(STRIDER_SIMAVR_FOUND ON)
  if(NOT TARGET strider::simavr)
    add_library(strider::simavr INTERFACE IMPORTED GLOBAL)
    set_target_properties(strider::simavr PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${STRIDER_SIMAVR_INCLUDE}"
      INTERFACE_LINK_LIBRARIES "${STRIDER_SIMAVR_LIB};${STRIDER_ELF_LIB}")
  endif()
endif()

get_property(_avr_reported GLOBAL PROPERTY STRIDER_AVR_REPORTED)
if(NOT _avr_reported)
  set_property(GLOBAL PROPERTY STRIDER_AVR_REPORTED ON)
  if(NOT STRIDER_AVR_FOUND)
    message(STATUS "Strider AVR: avr-g++/avr-size/avr-libc not found: AVR builds and checks are off "
                   "(apt-get install gcc-avr avr-libc binutils-avr)")
  endif()
  if(NOT STRIDER_SIMAVR_FOUND)
    message(STATUS "Strider AVR: libsimavr/libelf not found: simulated benchmark and bit-exact test are off "
                   "(apt-get install simavr libsimavr-dev libelf-dev)")
  endif()
endif()

# What gcc 5.4 needs for the library (see TOOLCHAIN.md): C++14, no exceptions,
# no RTTI, no thread-safe statics, dead code dropped per section.
set(STRIDER_AVR_CXX_FLAGS
  -mmcu=${STRIDER_AVR_MCU} -DF_CPU=${STRIDER_AVR_F_CPU}UL -std=gnu++14 -Os
  -fno-exceptions -fno-rtti -fno-threadsafe-statics -ffunction-sections -fdata-sections)

# strider_avr_firmware(NAME SOURCES src... [INCLUDES dir...] [DEFINES d...]
#                      [WARNINGS w...] [DEPENDS file...])
# DEPENDS adds files beyond the compiler's depfile, e.g. a header glob, so a
# header that appears later (seen through __has_include) triggers a rebuild.
function(strider_avr_firmware name)
  cmake_parse_arguments(ARG "" "" "SOURCES;INCLUDES;DEFINES;WARNINGS;DEPENDS" ${ARGN})
  set(elf ${CMAKE_CURRENT_BINARY_DIR}/${name}.elf)
  set(srcs)
  foreach(s IN LISTS ARG_SOURCES)
    get_filename_component(abs ${s} ABSOLUTE)
    list(APPEND srcs ${abs})
  endforeach()
  set(incs)
  foreach(i IN LISTS ARG_INCLUDES)
    list(APPEND incs -I${i})
  endforeach()
  set(defs)
  foreach(d IN LISTS ARG_DEFINES)
    list(APPEND defs -D${d})
  endforeach()
  # One compile+link step: the firmware is a handful of translation units.
  add_custom_command(
    OUTPUT ${elf}
    COMMAND ${STRIDER_AVR_CXX} ${STRIDER_AVR_CXX_FLAGS} ${ARG_WARNINGS} ${defs} ${incs}
            -MMD -MF ${elf}.d -MT ${elf}
            -Wl,--gc-sections -o ${elf} ${srcs}
    DEPENDS ${srcs} ${ARG_DEPENDS}
    DEPFILE ${elf}.d
    COMMENT "avr-g++ ${name}.elf"
    VERBATIM COMMAND_EXPAND_LISTS)
  add_custom_target(${name} ALL DEPENDS ${elf})
  set_target_properties(${name} PROPERTIES STRIDER_ELF ${elf})
endfunction()

# Every public header compiles on its own: a generated translation unit that
# only includes it (twice, to check the include guard). The glob is re-run at
# each build's configure check, so new headers get their tests.
function(strider_add_header_checks)
  cmake_parse_arguments(ARG "" "ROOT" "" ${ARGN})
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS RELATIVE ${ARG_ROOT} ${ARG_ROOT}/*.h)
  list(SORT headers)
  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/header_checks)
  file(MAKE_DIRECTORY ${gen_dir})
  foreach(h IN LISTS headers)
    string(MAKE_C_IDENTIFIER ${h} id)
    set(tu ${gen_dir}/${id}.cpp)
    set(content "// Compile check: ${h} on its own.\n#include \"${h}\"\n#include \"${h}\"\n")
    if(EXISTS ${tu})
      file(READ ${tu} old)
    else()
      set(old "")
    endif()
    if(NOT old STREQUAL content)
      file(WRITE ${tu} "${content}")
    endif()
    add_test(NAME headers/host/${h}
      COMMAND ${CMAKE_CXX_COMPILER} -std=c++17 -Wall -Wextra -Werror -I${ARG_ROOT}
              -c ${tu} -o ${gen_dir}/${id}.host.o)
    set_tests_properties(headers/host/${h} PROPERTIES LABELS "headers;host")
    if(STRIDER_AVR_FOUND)
      add_test(NAME headers/avr/${h}
        COMMAND ${STRIDER_AVR_CXX} ${STRIDER_AVR_CXX_FLAGS} -Wall -Werror -I${ARG_ROOT}
                -c ${tu} -o ${gen_dir}/${id}.avr.o)
      set_tests_properties(headers/avr/${h} PROPERTIES LABELS "headers;avr")
    endif()
  endforeach()
  list(LENGTH headers n)
  message(STATUS "Strider AVR: ${n} public headers get compile checks")
endfunction()
