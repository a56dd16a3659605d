# Fails when a per-instruction-set kernel object (core/tracer/tracer_kernel.cpp built
# with WHITTED_ISA=<isa>) defines a global symbol outside whitted::isa_<isa>.
# Such a symbol is an inline function or template the linker may merge with a
# copy from another object: an AVX2 copy could then run on the baseline path
# and crash older CPUs with SIGILL. Run with -DNM=... -DOBJECT=... -DISA=...
execute_process(COMMAND ${NM} --defined-only ${OBJECT}
  OUTPUT_VARIABLE symbols RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${NM} failed on ${OBJECT}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
# As the Itanium ABI mangles it: its length, then the name (8isa_avx2).
string(LENGTH "isa_${ISA}" length)
set(mangled "${length}isa_${ISA}")
set(inside 0)
set(outside "")
foreach(line IN LISTS lines)
  # Global definitions: text, data, read-only, bss, weak and unique symbols.
  if(NOT line MATCHES "^[0-9a-f]* [TDRBWVu] (.*)$")
    continue()
  endif()
  set(symbol "${CMAKE_MATCH_1}")
  # A pointer to the C++ runtime's personality routine: data, no code of ours.
  if(symbol MATCHES "^DW\\.ref\\.__gxx_personality_v0$")
    continue()
  endif()
  if(symbol MATCHES "${mangled}")
    math(EXPR inside "${inside} + 1")
  else()
    string(APPEND outside "\n  ${symbol}")
  endif()
endforeach()
if(inside EQUAL 0)
  message(FATAL_ERROR "${OBJECT} defines nothing in whitted::isa_${ISA}: not a kernel object?")
endif()
if(outside)
  message(FATAL_ERROR "${OBJECT} defines symbols outside whitted::isa_${ISA} (c++filt reads them):${outside}")
endif()
message(STATUS "${ISA}: ${inside} global symbols, all naming whitted::isa_${ISA}")
