# A manual page for every program, made at build time by Debian's help2man
# from the program's own --help, with what --help does not say (examples, exit
# status, related programs) from resources/man/PROGRAM.h2m; compressed as
# Debian installs them, into share/man/man1. Each program runs once for it,
# so the sanitizer builds, which install nothing, leave them out
# (WHITTED_MAN_PAGES, CMakePresets.json).
find_program(HELP2MAN help2man REQUIRED)

# program -> the line under NAME.
set(whitted_man_whitted "scene editor for a classic Whitted ray tracer")
set(whitted_man_whitted-render "render a Whitted scene file to an image")
set(whitted_man_whitted-farm "render a Whitted scene on a Slurm cluster")
set(whitted_man_whitted-field "write a field of small balls as a Whitted scene file")
set(whitted_man_whitted-numerics "measure where float and double Whitted renders part")
set(whitted_man_whitted-tradeoff "measure a Whitted scene's speed against its accuracy")

set(man_pages)
foreach(program whitted whitted-render whitted-farm whitted-field whitted-numerics
                whitted-tradeoff)
  set(page ${CMAKE_BINARY_DIR}/man/${program}.1)
  set(extra ${PROJECT_SOURCE_DIR}/resources/man/${program}.h2m)
  add_custom_command(OUTPUT ${page}.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
    COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen
            ${HELP2MAN} --no-info --section=1
            --version-string=${PROJECT_VERSION} "--name=${whitted_man_${program}}"
            --include=${extra} --output=${page} $<TARGET_FILE:${program}>
    COMMAND ${GZIP} -9nf ${page}
    DEPENDS ${program} ${extra}
    COMMENT "Manual page ${program}(1)" VERBATIM)
  list(APPEND man_pages ${page}.gz)
endforeach()
add_custom_target(whitted-man-pages ALL DEPENDS ${man_pages})
install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
