0 BEGIN PGM ROUNDARCS MM
1 L X+0 Y+0 Z-2 R0 FMAX
2 ; clockwise over the top of (5, 0), then clockwise over (15, 0): a cusp at (10, 0)
3 CC X+5 Y+0
4 C X+10 Y+0 DR- F100
5 RND R1
6 CC X+15 Y+0
7 C X+20 Y+0 DR-
8 L Z+10 FMAX
9 END PGM ROUNDARCS MM
