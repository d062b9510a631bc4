port: CYCLE85/CYCLE89 to CYCL DEF 201/202 not mapped yet (E0610); Klartext has the cycles
