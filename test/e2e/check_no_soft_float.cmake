# Fails when a firmware ELF links any of avr-libc's soft-float routines:
# a fixed-point firmware computes in integers only (a float call that slips
# in, as through a library's float API, costs about 1 KB of flash and the
# cycles of soft float).
#   cmake -DNM=avr-nm -DELF=<firmware.elf> -P check_no_soft_float.cmake
if(NOT EXISTS ${ELF})
  message("skipped: no ${ELF} (its build was skipped)")
  return()
endif()
execute_process(COMMAND ${NM} ${ELF} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} ${ELF} failed (${rc})")
endif()
string(REGEX MATCHALL "[^\n]* (__(add|sub|mul|div)sf3|__fix(uns)?sfsi|__float(un)?sisf|__(eq|ne|lt|le|gt|ge|un|cmp)sf2|__fp_[a-z]+)\n"
       hits "${symbols}")
if(hits)
  message(FATAL_ERROR "${ELF} links soft-float routines:\n${hits}")
endif()
message(STATUS "${ELF}: no soft-float routines")
