# StriderFirmware.cmake: builds the AVR firmware (src/, one ELF per robot
# model) from the host build as an external project with the AVR toolchain
# file, and exposes each ELF to host tools and tests:
#   target strider_firmware_<model>   builds it
#   property STRIDER_ELF              its path (<build>/src/strider_firmware_<model>.elf)
#   variable STRIDER_FIRMWARE_FOUND   ON when the AVR toolchain and the Arduino core are there
include(ExternalProject)

set(STRIDER_FIRMWARE_MODELS sprawl8 mammal8 dog12 hexapod18 spider12)
set(STRIDER_ARDUINO_AVR_DIR /usr/share/arduino/hardware/arduino/avr CACHE PATH "arduino-core-avr's hardware/arduino/avr")
find_program(STRIDER_FW_AVR_GCC avr-gcc)
find_program(STRIDER_FW_AVR_GXX avr-g++)
set(STRIDER_FIRMWARE_FOUND OFF)
if(STRIDER_FW_AVR_GCC AND STRIDER_FW_AVR_GXX AND EXISTS ${STRIDER_ARDUINO_AVR_DIR}/cores/arduino/Arduino.h)
  set(STRIDER_FIRMWARE_FOUND ON)
else()
  message(STATUS "Strider firmware: not built (apt-get install gcc-avr avr-libc arduino-core-avr)")
  return()
endif()

set(STRIDER_FIRMWARE_DIR ${CMAKE_BINARY_DIR}/src)
set(_fw_byproducts)
foreach(model IN LISTS STRIDER_FIRMWARE_MODELS)
  list(APPEND _fw_byproducts ${STRIDER_FIRMWARE_DIR}/strider_firmware_${model}.elf)
endforeach()
string(REPLACE ";" "$<SEMICOLON>" _fw_models "${STRIDER_FIRMWARE_MODELS}")
# Local copies of the firmware's libraries (FetchContent source overrides),
# passed on to the sub-build.
set(_fw_fetch_args)
foreach(dep ADAFRUIT_PWM_SERVO_DRIVER ADAFRUIT_BUSIO)
  if(FETCHCONTENT_SOURCE_DIR_${dep})
    list(APPEND _fw_fetch_args -DFETCHCONTENT_SOURCE_DIR_${dep}=${FETCHCONTENT_SOURCE_DIR_${dep}})
  endif()
endforeach()
ExternalProject_Add(strider_firmware
  SOURCE_DIR ${PROJECT_SOURCE_DIR}/src
  BINARY_DIR ${STRIDER_FIRMWARE_DIR}
  CMAKE_GENERATOR ${CMAKE_GENERATOR}
  CMAKE_ARGS
    -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/cmake/avr-gcc.toolchain.cmake
    -DCMAKE_BUILD_TYPE=MinSizeRel
    -DSTRIDER_ROOT=${PROJECT_SOURCE_DIR}
    -DARDUINO_AVR_DIR=${STRIDER_ARDUINO_AVR_DIR}
    -DSTRIDER_MODELS=${_fw_models}
    ${_fw_fetch_args}
  BUILD_ALWAYS ON          # the library's headers change without the sub-build knowing
  INSTALL_COMMAND ""
  BUILD_BYPRODUCTS ${_fw_byproducts}
  USES_TERMINAL_BUILD ON)

foreach(model IN LISTS STRIDER_FIRMWARE_MODELS)
  add_custom_target(strider_firmware_${model} DEPENDS strider_firmware)
  set_target_properties(strider_firmware_${model} PROPERTIES
    STRIDER_ELF ${STRIDER_FIRMWARE_DIR}/strider_firmware_${model}.elf)
endforeach()
