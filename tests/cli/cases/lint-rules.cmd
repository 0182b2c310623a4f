$TAPE lint --rules
