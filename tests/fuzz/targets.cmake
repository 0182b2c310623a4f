# The fuzz targets: tests/fuzz/NAME_fuzz.cpp with its seed corpus in tests/fuzz/corpus/NAME/.
# One line: scripts/fuzz.sh reads the list from it.
# The corpus files of those in TAPE_FUZZ_LEADING_BYTES also replay behind every leading byte 0..127.
set(TAPE_FUZZ_TARGETS decode loader holes eia_table format_spec device_string adapter_packet dnc_request five_track label restore adapter_settings adapter_host adapter_emulate scan_geometry binary_tape dump telecode_table doubts_file picture)
set(TAPE_FUZZ_LEADING_BYTES decode loader)
# The scan geometry stage reads pictures with OpenCV: a target only where the build has it.
if(NOT TAPE_HAVE_OPENCV)
  list(REMOVE_ITEM TAPE_FUZZ_TARGETS scan_geometry)
endif()
