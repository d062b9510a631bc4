0 BEGIN PGM APPRARC MM
1 TOOL DEF 1 L+0 R+2
2 TOOL CALL 1 Z S3000
3 L X+40 Y+10 Z+5 R0 FMAX M3
4 L Z-10 F500
5 ; the manual's example: a half circle R10 into (10, 20), clockwise (RR, R+)
6 APPR CT X+10 Y+20 Z-10 CCA180 R+10 RR F100
7 L X+20 Y+35
8 L X+50 Y+35
9 ; leave on a quarter circle R8 turning right (RR, R+: clockwise)
10 DEP CT CCA90 R+8 R0 F200
11 L Z+5 FMAX
12 L X-20 Y+5 FMAX
13 L Z-5 F500
14 ; a line tangent to an R5 arc into (0, 0), counterclockwise (RL, R+)
15 APPR LCT X+0 Y+0 R+5 RL F100
16 L X+30
17 ; an R5 arc turning left, then the line tangent to it to (40, 20)
18 DEP LCT X+40 Y+20 R+5 R0
19 L X+30 Y-20 Z+5 FMAX
20 L Z-5 F500
21 ; into an arc: LT along its tangent at (20, -10), PH at (25, -10)
22 CC X+20 Y-20
23 APPR LT X+20 Y-10 LEN5 RL F100
24 C X+10 Y-20 DR+
25 DEP LT LEN5 R0
26 L Z+50 FMAX M5
27 END PGM APPRARC MM
