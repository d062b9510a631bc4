port: G85/G86/G89 to CYCL DEF 201/202 not mapped yet (E0610); Klartext has the cycles
