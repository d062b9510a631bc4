port: G84 to CYCL DEF 207 not mapped yet (E0610); Klartext has the cycle
