# The fuzz targets: tests/fuzz/NAME_fuzz.cpp with its seed corpus in tests/fuzz/corpus/NAME/.
# One line: scripts/fuzz.sh reads the list from it.
# The corpus files of those in TAPE_FUZZ_LEADING_BYTES also replay behind every leading byte 0..127.
set(TAPE_FUZZ_TARGETS decode loader holes eia_table format_spec machine_profile device_string adapter_packet dnc_request five_track label restore adapter_settings adapter_host adapter_emulate scan_geometry binary_tape dump telecode_table motion dnc_config dnc_control doubts_file picture)
set(TAPE_FUZZ_LEADING_BYTES decode loader)
# The scan geometry stage reads pictures with OpenCV: a target only where the build has it.
if(NOT TAPE_HAVE_OPENCV)
  list(REMOVE_ITEM TAPE_FUZZ_TARGETS scan_geometry)
endif()
# The DNC config is read by the tape program's reader (tools/tape/dnc_config/), built into its target
# with toml++ and CLI11's headers: a target only where the build has toml++.
set(TAPE_FUZZ_EXTRA_SOURCES_dnc_config ${PROJECT_SOURCE_DIR}/tools/tape/dnc_config/with_toml.cpp)
set(TAPE_FUZZ_EXTRA_LIBRARIES_dnc_config tomlplusplus::tomlplusplus CLI11::CLI11)
if(NOT tomlplusplus_FOUND)
  list(REMOVE_ITEM TAPE_FUZZ_TARGETS dnc_config)
endif()
