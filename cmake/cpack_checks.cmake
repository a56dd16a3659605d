# Read by cpack before it packs (CPACK_PROJECT_CONFIG_FILE, cmake/install.cmake):
# a package built for the packing machine's own CPU may not start on another.
if(CPACK_WHITTED_NATIVE AND NOT CPACK_WHITTED_ALLOW_NATIVE)
  message(FATAL_ERROR
    "this build is optimised for this machine's CPU (WHITTED_NATIVE=ON), and a "
    "package of it may not start on another; configure a build with "
    "-DWHITTED_NATIVE=OFF to package it")
endif()
