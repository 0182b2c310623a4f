# Numbers out of range are usage errors found before the device is opened: nothing is written.
for option in "--rate nan" "--rate -5" "--rate 1e-300" "--rate 0" "--rate 100001" "--delay -1" "--delay 60001" \
    "--xon-timeout -1" "--xon-timeout nan" "--xon-timeout 86401"; do
  $TAPE feed tapes/16k20f3s5-turning.txt file:fed.ptp $option; echo "$option: exit $?"
done
ls
