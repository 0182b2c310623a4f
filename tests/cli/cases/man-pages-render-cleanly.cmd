# Every man page as man shows it, in a UTF-8 terminal and in the POSIX locale (groff's ascii device, where
# Cyrillic is spelt in Latin letters), 80 columns wide: no troff or tbl warning.
for page in tapes/../man/*.[157]; do
  for lang in C C.UTF-8; do
    warnings=$(LANG=$lang LC_ALL=$lang MANWIDTH=80 man -l "$page" 2>&1 >/dev/null)
    [ -z "$warnings" ] || echo "$(basename "$page") ($lang): $warnings"
  done
done
LANG=C LC_ALL=C MANWIDTH=80 man -l tapes/../man/tape-usb.7 | grep -o 'FS-1501\|PL-150-class' | sort -u
