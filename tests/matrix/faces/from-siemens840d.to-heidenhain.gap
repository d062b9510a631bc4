port: CYCLE71 to CYCL DEF 232 not mapped yet (E0601 from the writer)
