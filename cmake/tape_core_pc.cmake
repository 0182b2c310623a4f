# Run by `cmake --install`: writes tape_core.pc with the prefix of this installation, which is known
# only now (--prefix may differ from CMAKE_INSTALL_PREFIX at configure time). The caller sets
# TAPE_PC_IN, TAPE_PC_OUT, TAPE_PC_LIBDIR, TAPE_PC_INCLUDEDIR (as GNUInstallDirs gives them),
# TAPE_PC_VERSION and TAPE_PC_SANITIZE (the sanitizer flags users need too, with a space before, or empty).
set(TAPE_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
foreach(dir LIBDIR INCLUDEDIR)
  # Relative directories are under the prefix; an absolute one stays as given.
  if(NOT IS_ABSOLUTE "${TAPE_PC_${dir}}")
    set(TAPE_PC_${dir} "\${prefix}/${TAPE_PC_${dir}}")
  endif()
endforeach()
configure_file("${TAPE_PC_IN}" "${TAPE_PC_OUT}" @ONLY)
