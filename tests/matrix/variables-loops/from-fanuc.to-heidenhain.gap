port: #n variables, WHILE/IF/GOTO to Q parameters and FN 9..12 jumps not mapped yet (E0601 from the writer)
