# Installing (`cmake --install build --prefix P`) and packaging (`cpack -G DEB`
# in the build directory) as a desktop program, in the FHS layout:
#   bin/                     whitted, whitted-render, whitted-farm, whitted-numerics, whitted-tradeoff,
#                            whitted-field
#   lib/whitted/             whitted_oiio.so, the plug-in that reads and writes image files
#   share/applications/      the .desktop file (opens scene files in the editor)
#   share/metainfo/          AppStream metadata
#   share/mime/packages/     the scene files' MIME type
#   share/icons/hicolor/     the icon, scalable and as PNGs
#   share/whitted/scenes/    the example scenes
#   share/man/man1/          the programs' manual pages (cmake/man_pages.cmake)
#   share/doc/whitted/       copyright and changelog, as Debian wants them
# A package must run on any x86-64 machine: cpack refuses a build configured
# with WHITTED_NATIVE=ON (configure it with -DWHITTED_NATIVE=OFF).
include(GNUInstallDirs)

set(WHITTED_APP_ID io.github.whitted.Whitted)
set(WHITTED_RESOURCES ${PROJECT_SOURCE_DIR}/resources)

install(TARGETS whitted whitted-render whitted-farm whitted-numerics whitted-tradeoff whitted-field
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS whitted_oiio LIBRARY DESTINATION ${WHITTED_CODEC_DIR})
install(FILES ${WHITTED_RESOURCES}/${WHITTED_APP_ID}.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${WHITTED_RESOURCES}/${WHITTED_APP_ID}.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES ${WHITTED_RESOURCES}/${WHITTED_APP_ID}.mime.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages RENAME ${WHITTED_APP_ID}.xml)
install(FILES ${WHITTED_RESOURCES}/icons/whitted.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps
        RENAME ${WHITTED_APP_ID}.svg)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/
        DESTINATION ${CMAKE_INSTALL_DATADIR}/whitted/scenes
        FILES_MATCHING PATTERN "*.json" PATTERN "README.md")

# The PNG sizes desktops look for, rendered from the one SVG at build time.
find_program(RSVG_CONVERT rsvg-convert REQUIRED)
set(WHITTED_ICON_SIZES 16 32 48 64 128 256)
set(icon_pngs)
foreach(size IN LISTS WHITTED_ICON_SIZES)
  set(png ${CMAKE_BINARY_DIR}/icons/${size}/${WHITTED_APP_ID}.png)
  add_custom_command(OUTPUT ${png}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/icons/${size}
    COMMAND ${RSVG_CONVERT} -w ${size} -h ${size} -o ${png} ${WHITTED_RESOURCES}/icons/whitted.svg
    DEPENDS ${WHITTED_RESOURCES}/icons/whitted.svg
    COMMENT "Icon ${size}x${size}" VERBATIM)
  list(APPEND icon_pngs ${png})
  install(FILES ${png} DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
endforeach()
add_custom_target(whitted-icons ALL DEPENDS ${icon_pngs})

find_program(GZIP gzip REQUIRED)
if(WHITTED_MAN_PAGES)
  include(${CMAKE_CURRENT_LIST_DIR}/man_pages.cmake)
endif()

# Debian's copyright file and, for a native package, changelog.gz.
set(changelog ${CMAKE_BINARY_DIR}/doc/changelog.gz)
add_custom_command(OUTPUT ${changelog}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/doc
  COMMAND ${GZIP} -9nc ${WHITTED_RESOURCES}/debian/changelog > ${changelog}
  DEPENDS ${WHITTED_RESOURCES}/debian/changelog
  COMMENT "changelog.gz")
add_custom_target(whitted-changelog ALL DEPENDS ${changelog})
install(FILES ${WHITTED_RESOURCES}/debian/copyright ${changelog}
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_PACKAGE_NAME whitted)
set(CPACK_PACKAGE_VENDOR "The Whitted developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Scene editor for a classic Whitted ray tracer")
# One string, its lines under 80 columns: cpack indents each as Debian's
# Description wants (a CMake list's items would be joined by semicolons).
set(CPACK_PACKAGE_DESCRIPTION
    "Place spheres, lights and materials with the mouse and see every edit\n"
    "rendered again at once, with shadows, reflection and refraction, in float\n"
    "or double precision.\n"
    "\n"
    "Also the command-line renderer whitted-render, rendering on a Slurm\n"
    "cluster with whitted-farm, and the Python module whitted.")
string(CONCAT CPACK_PACKAGE_DESCRIPTION ${CPACK_PACKAGE_DESCRIPTION})
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT
    "Seed d7443446 maintainers <maintainers@users.noreply.h-seed-d7443446.example>")
set(CPACK_STRIP_FILES ON)
# cpack reads these from CPackConfig.cmake: a native build is refused
# (cmake/cpack_checks.cmake) unless CPACK_WHITTED_ALLOW_NATIVE is set, as the
# package's own tests do to check its contents.
set(CPACK_WHITTED_NATIVE ${WHITTED_NATIVE})
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_CURRENT_LIST_DIR}/cpack_checks.cmake)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# Depends from the shared libraries the programs link (dpkg-shlibdeps), plus
# what no program links but Qt loads at run time: the SVG icon plugins; and
# the Python the module was built for, with NumPy, which it imports.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6")
if(WHITTED_BUILD_PYTHON)
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", python3 (>= ${WHITTED_PYTHON_VERSION}), "
         "python3 (<< ${WHITTED_PYTHON_VERSION}.99), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "desktop-file-utils, shared-mime-info")
include(CPack)
