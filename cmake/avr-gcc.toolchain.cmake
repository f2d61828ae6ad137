# Cross toolchain for the ATmega2560 with Debian's gcc-avr (5.4) and
# avr-libc. Used by the firmware project in src/ (built from the top-level
# project as an external project, or alone:
#   cmake -S src -B out/firmware -DCMAKE_TOOLCHAIN_FILE=cmake/avr-gcc.toolchain.cmake).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR avr)

find_program(AVR_GCC avr-gcc REQUIRED)
find_program(AVR_GXX avr-g++ REQUIRED)
# The gcc wrappers of ar and ranlib: static libraries of -flto objects need
# the linker plugin (as PlatformIO's builder uses them).
find_program(AVR_GCC_AR avr-gcc-ar REQUIRED)
find_program(AVR_GCC_RANLIB avr-gcc-ranlib REQUIRED)
find_program(AVR_OBJCOPY avr-objcopy REQUIRED)
find_program(AVR_SIZE avr-size REQUIRED)

set(CMAKE_C_COMPILER ${AVR_GCC})
set(CMAKE_CXX_COMPILER ${AVR_GXX})
set(CMAKE_ASM_COMPILER ${AVR_GCC})
set(CMAKE_AR ${AVR_GCC_AR} CACHE FILEPATH "avr-gcc-ar" FORCE)
set(CMAKE_RANLIB ${AVR_GCC_RANLIB} CACHE FILEPATH "avr-gcc-ranlib" FORCE)

# Compiler checks link a program: a bare main() links fine for the AVR, but
# keep the checks from needing the MCU flags.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
