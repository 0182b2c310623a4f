# The fuzz targets: tests/fuzz/NAME_fuzz.cpp with its seed corpus in tests/fuzz/corpus/NAME/.
# The corpus files of those in TAPE_FUZZ_LEADING_BYTES also replay behind every leading byte 0..127.
set(TAPE_FUZZ_TARGETS decode loader holes eia_table format_spec device_string adapter_packet dnc_request five_track
    label restore adapter_settings adapter_host adapter_emulate binary_tape dump telecode_table)
set(TAPE_FUZZ_LEADING_BYTES decode loader)
