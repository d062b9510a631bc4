0 BEGIN PGM ROUNDARC MM
1 TOOL DEF 1 L+0 R+0
2 TOOL CALL 1 Z S2000
3 L X+0 Y+0 Z-2 R0 FMAX M3
4 ; along +X, round R1 into a clockwise half circle round (15, 0)
5 L X+10 F200
6 RND R1
7 CR X+20 Y+0 R+5 DR-
8 ; down, round R2 into a counterclockwise arc round the pole (20, -15)
9 L Y-10
10 RND R2
11 CC X+20 Y-15
12 C X+15 Y-15 DR+
13 ; out of that arc (heading -Y at (15, -15)), round R1 into a line along -X
14 RND R1
15 L X+0
16 L Z+10 FMAX
17 END PGM ROUNDARC MM
