0 BEGIN PGM ROUNDCT MM
1 L X+0 Y+0 Z-2 R0 FMAX
2 L X+10 F100
3 ; a rounding after a CT arc runs; one before a CT is not run yet
4 CT X+20 Y+10
5 RND R1
6 L X+0
7 RND R1
8 CT X-10 Y+20
9 L Z+10 FMAX
10 END PGM ROUNDCT MM
