# Run by `cmake --install`: writes tape_core.pc with the prefix of this installation, which is known
# only now (--prefix may differ from CMAKE_INSTALL_PREFIX at configure time). The caller sets
# TAPE_PC_IN, TAPE_PC_OUT, TAPE_PC_LIBDIR, TAPE_PC_INCLUDEDIR (as GNUInstallDirs gives them),
# TAPE_PC_VERSION, TAPE_PC_SANITIZE (the sanitizer flags users need too, with a space before, or empty)
# and TAPE_PC_PRIVATE_LIBS (full paths of libraries to name on Libs).
set(TAPE_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
foreach(dir LIBDIR INCLUDEDIR)
  # Relative directories are under the prefix; an absolute one stays as given.
  if(NOT IS_ABSOLUTE "${TAPE_PC_${dir}}")
    set(TAPE_PC_${dir} "\${prefix}/${TAPE_PC_${dir}}")
  endif()
endforeach()
# Libraries the static library needs that have no pkg-config file of their own (OpenCV's modules on
# Debian without libopencv-dev): named on Libs, as -l flags.
set(TAPE_PC_EXTRA_LIBS "")
foreach(lib ${TAPE_PC_PRIVATE_LIBS})
  get_filename_component(name "${lib}" NAME_WE)
  string(REGEX REPLACE "^lib" "" name "${name}")
  string(APPEND TAPE_PC_EXTRA_LIBS " -l${name}")
endforeach()
configure_file("${TAPE_PC_IN}" "${TAPE_PC_OUT}" @ONLY)
