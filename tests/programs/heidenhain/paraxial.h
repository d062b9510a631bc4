0 BEGIN PGM PARAXIAL MM
1 TOOL DEF 2 L+10 R+3
2 TOOL CALL 2 Z S1000 DR+0.5
3 L X+0 Y+0 Z+5 R0 FMAX
4 ; R+ lengthens by the radius 3 + DR 0.5: X ends at 23.5
5 L X+20 R+ F100
6 ; R- shortens: Y ends at 6.5
7 L Y+10 R-
8 L IX-10 R+
9 L Z+50 FMAX
10 END PGM PARAXIAL MM
