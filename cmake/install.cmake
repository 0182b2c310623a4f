# What `cmake --install build [--prefix DIR]` puts where, every path relative to the prefix (GNUInstallDirs),
# so that an install to ~/.local or a temporary folder writes nowhere else. Two components: runtime (the
# programs, their man pages, bash completion, udev rule and code tables: the tape .deb) and dev (the library
# tape_core for other programs: libtape-core-dev).

# The programs' bash completion, made by the program itself whenever it is linked (so that building the tape
# target alone, as the demo does, leaves nothing for the install to miss).
set(TAPE_COMPLETION ${PROJECT_BINARY_DIR}/completion/tape)
add_custom_command(TARGET tape POST_BUILD
                   COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:tape> -DOUTPUT=${TAPE_COMPLETION}
                           -P ${PROJECT_SOURCE_DIR}/cmake/bash_completion.cmake
                   VERBATIM)

# Man pages are installed compressed, as Debian's policy asks; man reads them so.
set(TAPE_MAN_PAGES man/tape.1 man/tape-archive.1 man/tape-plot.1 man/tape-damage.1 man/tape-image.5 man/tape-devices.7 man/tape-usb.7)
foreach(page ${TAPE_MAN_PAGES})
  get_filename_component(name ${page} NAME)
  string(REGEX REPLACE ".*\\." "" section ${name})
  set(gz ${PROJECT_BINARY_DIR}/man/${name}.gz)
  add_custom_command(OUTPUT ${gz} COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
                     COMMAND gzip -9n -c ${PROJECT_SOURCE_DIR}/${page} > ${gz}
                     DEPENDS ${PROJECT_SOURCE_DIR}/${page})
  list(APPEND TAPE_MAN_GZ ${gz})
  install(FILES ${gz} DESTINATION ${CMAKE_INSTALL_MANDIR}/man${section} COMPONENT runtime)
endforeach()
add_custom_target(tape_man ALL DEPENDS ${TAPE_MAN_GZ})
add_dependencies(tape tape_man)

install(TARGETS tape RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
# The picture module, where the programs look for it: ../LIBDIR/tape beside them (CMakeLists.txt).
if(TARGET tape_pictures)
  install(TARGETS tape_pictures LIBRARY DESTINATION ${TAPE_PICTURE_MODULE_DIR} COMPONENT runtime)
endif()
if(TARGET tape_plot)
  install(TARGETS tape_plot LIBRARY DESTINATION ${TAPE_PICTURE_MODULE_DIR} COMPONENT runtime)
endif()
# Built by `cmake --build build`, not by the demo's build of the tape target alone: installed when built.
install(TARGETS tape-damage tape-adapter-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime OPTIONAL)
install(FILES ${TAPE_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions COMPONENT runtime)
install(FILES data/eia-rs244.tab data/ita2.tab data/mtk2.tab data/elliott900.tab data/elliott920.tab DESTINATION ${CMAKE_INSTALL_DATADIR}/tape
        COMPONENT runtime)
install(FILES ${TAPE_MACHINE_FILES} data/machines/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/tape/machines
        COMPONENT runtime)
# tape dnc's systemd unit (with the installed binary's path) and its sample configuration; the unit goes to the
# prefix's lib/systemd/system, systemd's own folder when the prefix is /usr.
set(TAPE_BINDIR ${CMAKE_INSTALL_FULL_BINDIR})
set(TAPE_DATADIR ${CMAKE_INSTALL_FULL_DATADIR}/tape)
configure_file(packaging/tape-dnc.service.in ${PROJECT_BINARY_DIR}/tape-dnc.service @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tape-dnc.service DESTINATION lib/systemd/system COMPONENT runtime)
install(FILES packaging/dnc.toml DESTINATION ${CMAKE_INSTALL_DATADIR}/tape COMPONENT runtime)

# The udev rule goes to the prefix's lib/udev/rules.d (not CMAKE_INSTALL_LIBDIR's multiarch folder): udev's
# own folder when the prefix is /usr (a .deb), and a copy to put into /etc/udev/rules.d otherwise (README,
# Install). TAPE_SYSTEM_UDEV_RULES, for a system-wide install by root, puts it in udev's folder as pkg-config
# names it, whatever the prefix.
option(TAPE_SYSTEM_UDEV_RULES "Install the udev rule into udev's own folder (pkg-config udev), not under the prefix"
       OFF)
set(TAPE_UDEV_RULES_DIR lib/udev/rules.d)
if(TAPE_SYSTEM_UDEV_RULES)
  pkg_get_variable(TAPE_UDEVDIR udev udevdir)
  if(NOT TAPE_UDEVDIR)
    message(FATAL_ERROR "TAPE_SYSTEM_UDEV_RULES: pkg-config does not know udev's folder (apt-get install udev)")
  endif()
  set(TAPE_UDEV_RULES_DIR ${TAPE_UDEVDIR}/rules.d)
endif()
install(FILES udev/70-tape-adapter.rules DESTINATION ${TAPE_UDEV_RULES_DIR} COMPONENT runtime)

# The library: find_package(tape_core) gives tape::tape_core, and pkg-config tape_core the same, with what a
# program using it needs: C++20 (the headers use std::span) and the include directory.
include(CMakePackageConfigHelpers)
target_compile_features(tape_core PUBLIC cxx_std_20)
install(TARGETS tape_core EXPORT tape_coreTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev)
install(DIRECTORY include/tape DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)
set(TAPE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tape_core)
install(EXPORT tape_coreTargets NAMESPACE tape:: DESTINATION ${TAPE_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(cmake/tape_coreConfig.cmake.in ${PROJECT_BINARY_DIR}/tape_coreConfig.cmake
                              INSTALL_DESTINATION ${TAPE_CMAKE_DIR})
# 0.x: a new minor version may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tape_coreConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tape_coreConfig.cmake ${PROJECT_BINARY_DIR}/tape_coreConfigVersion.cmake
        DESTINATION ${TAPE_CMAKE_DIR} COMPONENT dev)
# A library built with the sanitizers (TAPE_SANITIZE) links only into programs built with them too.
set(TAPE_PC_SANITIZE "")
if(TAPE_SANITIZE)
  list(JOIN TAPE_SANITIZE_FLAGS " " TAPE_PC_SANITIZE)
  set(TAPE_PC_SANITIZE " ${TAPE_PC_SANITIZE}")
endif()
# tape_core.pc is written at install time (cmake/tape_core_pc.cmake): only then is the prefix known.
install(CODE "set(TAPE_PC_IN \"${PROJECT_SOURCE_DIR}/tape_core.pc.in\")
  set(TAPE_PC_OUT \"${PROJECT_BINARY_DIR}/tape_core.pc\")
  set(TAPE_PC_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
  set(TAPE_PC_INCLUDEDIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
  set(TAPE_PC_VERSION \"${PROJECT_VERSION}\")
  set(TAPE_PC_SANITIZE \"${TAPE_PC_SANITIZE}\")
  set(TAPE_PC_PRIVATE_LIBS \"${CMAKE_DL_LIBS}\")
  include(\"${PROJECT_SOURCE_DIR}/cmake/tape_core_pc.cmake\")" COMPONENT dev)
install(FILES ${PROJECT_BINARY_DIR}/tape_core.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)
