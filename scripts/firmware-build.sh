#!/usr/bin/env bash
# Cross-compiles the USB adapter's core (firmware/core) for a Cortex-M0+ with Debian's
# gcc-arm-none-eabi and picolibc, links it with firmware/size_probe (the core and a made-up board),
# and prints the flash and RAM it takes. Exit 0 when it builds; 77 (skipped) when the cross compiler
# is missing, saying which packages bring it.
set -euo pipefail
cd "$(dirname "$0")/.."
cxx=${ARM_CXX:-arm-none-eabi-g++}
if ! command -v "$cxx" >/dev/null; then
  echo "firmware-build: skipped: no $cxx (bash scripts/install-deps.sh firmware installs it)" >&2
  exit 77
fi
out=${1:-build-firmware}
mkdir -p "$out"
flags=(-mcpu=cortex-m0plus -mthumb -Os -std=c++20 -ffreestanding -fno-exceptions -fno-rtti -fno-threadsafe-statics
       -ffunction-sections -fdata-sections -Wall -Wextra -Wpedantic -Werror --specs=picolibcpp.specs -Ifirmware)
objects=()
for src in firmware/core/*.cpp firmware/size_probe/main.cpp; do
  obj="$out/$(echo "$src" | tr / _).o"
  "$cxx" "${flags[@]}" -c "$src" -o "$obj"
  objects+=("$obj")
done
# A part with 256 KiB of flash and 32 KiB of RAM (an RP2040 has more, a SAMD21 as much); 2 KiB of stack.
"$cxx" "${flags[@]}" -Wl,--gc-sections -Wl,--defsym=__flash=0x0 -Wl,--defsym=__flash_size=0x40000 \
  -Wl,--defsym=__ram=0x20000000 -Wl,--defsym=__ram_size=0x8000 -Wl,--defsym=__stack_size=0x800 \
  "${objects[@]}" -o "$out/size_probe.elf"
arm-none-eabi-size "${objects[@]}" "$out/size_probe.elf"
read -r text data bss _ < <(arm-none-eabi-size "$out/size_probe.elf" | tail -n 1)
echo "firmware-build: Cortex-M0+: flash $((text + data)) bytes, RAM $((data + bss)) bytes (2048 of it stack)"
