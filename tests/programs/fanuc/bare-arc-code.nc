%
O1001 (a G02 alone sets the mode; the next block moves without a centre)
G20 G17 G40 G49 G80 G90
T1 M06
G43 H01 Z1.
S1000 M03
G00 X0. Y0.
G01 Z-.1 F10.
G02
X1. Y1.
G00 Z1.
M30
%
