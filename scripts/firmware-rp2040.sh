#!/usr/bin/env bash
# Builds the tape adapter's firmware for a Raspberry Pi Pico (firmware/rp2040 with the shared core,
# firmware/core): boot stage 2 with its CRC32 (scripts/rp2040_boot2.py), the image as
# OUT/tape-adapter-rp2040.elf and OUT/tape-adapter-rp2040.uf2 (scripts/elf2uf2.py), and prints its flash
# and RAM against the budget (32 KB flash, 16 KB RAM, its 4 KB stack included). Exit 77 (skipped) when the
# cross compiler is missing; 1 when the image does not build or is over budget.
set -euo pipefail
cd "$(dirname "$0")/.."
cxx=${ARM_CXX:-arm-none-eabi-g++}
if ! command -v "$cxx" >/dev/null; then
  echo "firmware-rp2040: skipped: no $cxx (bash scripts/install-deps.sh firmware installs it)" >&2
  exit 77
fi
out=${1:-build-firmware}/rp2040
mkdir -p "$out"
cpu=(-mcpu=cortex-m0plus -mthumb)
flags=("${cpu[@]}" -Os -std=c++20 -ffreestanding -fno-exceptions -fno-rtti -fno-threadsafe-statics
       -ffunction-sections -fdata-sections -Wall -Wextra -Wpedantic -Werror --specs=picolibcpp.specs -Ifirmware)

# Boot stage 2 runs from SRAM at 0x20041F00, where the boot ROM copies it.
"$cxx" "${cpu[@]}" -c firmware/rp2040/boot2.S -o "$out/boot2.o"
"$cxx" "${cpu[@]}" -nostdlib -nostartfiles -Wl,-Ttext=0x20041F00 -Wl,-e,_stage2_boot "$out/boot2.o" -o "$out/boot2.elf"
arm-none-eabi-objcopy -O binary "$out/boot2.elf" "$out/boot2.bin"
python3 scripts/rp2040_boot2.py "$out/boot2.bin" "$out/boot2_crc.S"
"$cxx" "${cpu[@]}" -c "$out/boot2_crc.S" -o "$out/boot2_crc.o"

objects=("$out/boot2_crc.o")
for src in firmware/core/*.cpp firmware/rp2040/*.cpp; do
  obj="$out/$(basename "$(dirname "$src")")_$(basename "$src" .cpp).o"
  "$cxx" "${flags[@]}" -c "$src" -o "$obj"
  objects+=("$obj")
done
elf=$out/tape-adapter-rp2040.elf
"$cxx" "${flags[@]}" -nostartfiles -Wl,--gc-sections -T firmware/rp2040/rp2040.ld "${objects[@]}" -o "$elf"
python3 scripts/elf2uf2.py "$elf" "$out/tape-adapter-rp2040.uf2"

read -r text data bss _ < <(arm-none-eabi-size "$elf" | tail -n 1)
flash=$((text + data)) ram=$((data + bss))
echo "firmware-rp2040: $elf: flash $flash bytes (budget 32768), RAM $ram bytes with 4096 of stack (budget 16384)"
if [ "$flash" -gt 32768 ] || [ "$ram" -gt 16384 ]; then
  echo "firmware-rp2040: over budget" >&2
  exit 1
fi
