$(dirname "$TAPE")/tape-damage --help
