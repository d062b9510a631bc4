0 BEGIN PGM GLOBALQ MM
1 ; a subprogram kept as its own file: its caller set Q1800 before CALL PGM
2 FN 0: Q1 = +10
3 L X+Q1 Y+QL5 Z+50 R0 FMAX
4 L Z+Q1800 R0 FMAX
5 L X+0 FMAX
6 END PGM GLOBALQ MM
