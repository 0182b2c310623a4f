# `cpack -G DEB` in the build folder: tape_VERSION_ARCH.deb (the programs, man pages, bash completion, udev
# rule, code tables) and libtape-core-dev_VERSION_ARCH.deb (the library, its headers, CMake and pkg-config
# files), installing under /usr. The programs' library dependencies are found by dpkg-shlibdeps (dpkg-dev).
set(CPACK_PACKAGE_NAME tape)
set(CPACK_PACKAGE_VENDOR "the tape project")
set(CPACK_PACKAGE_CONTACT "tape developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "punched paper tape for NC machine tools")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
    "Turns part programs into 8-track tape images and back (ISO 7-bit, EIA RS-244, 5-track codes), lints
ГОСТ 20999-83, Fanuc and LinuxCNC programs, restores damaged tapes from several reads, and reads and punches
through serial lines and USB tape adapters.")
set(CPACK_COMPONENT_DEV_DESCRIPTION "The tape_core library (codec, image formats, program loader, devices), its
headers, and the files find_package(tape_core) and pkg-config use.")

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME tape)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION utils)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "udev")
# tape archive opens nettle with dlopen (src/archive/digest.cpp), which dpkg-shlibdeps cannot see.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "libnettle8")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME libtape-core-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
# A static library: what links it needs the USB libraries' development files (tape_coreConfig.cmake, tape_core.pc).
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libusb-1.0-0-dev, libhidapi-dev, pkg-config, libnettle8")
# Its scan and pictures load the picture module, which the tape package installs with OpenCV's libraries.
set(CPACK_DEBIAN_DEV_PACKAGE_SUGGESTS "tape")
include(CPack)
