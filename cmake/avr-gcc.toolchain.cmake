# Cross toolchain for the ATmega2560 with Debian's gcc-avr (5.4) and
# avr-libc. Used by the firmware project in src/ (built from the top-level
# project as an external project, or alone:
#   cmake -S src -B out/firmware -DCMAKE_TOOLCHAIN_FILE=cmake/avr-gcc.toolchain.cmake).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR avr)

find_program(AVR_GCC avr-gcc REQUIRED)
find_program(AVR_GXX avr-g++ REQUIRED)
find_program(AVR_AR avr-ar REQUIRED)
find_program(AVR_RANLIB avr-ranlib REQUIRED)
find_program(AVR_OBJCOPY avr-objcopy REQUIRED)
find_program(AVR_SIZE avr-size REQUIRED)

set(CMAKE_C_COMPILER ${AVR_GCC})
set(CMAKE_CXX_COMPILER ${AVR_GXX})
set(CMAKE_ASM_COMPILER ${AVR_GCC})
set(CMAKE_AR ${AVR_AR} CACHE FILEPATH "avr-ar")
set(CMAKE_RANLIB ${AVR_RANLIB} CACHE FILEPATH "avr-ranlib")

# Compiler checks link a program: a bare main() links fine for the AVR, but
# keep the checks from needing the MCU flags.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
