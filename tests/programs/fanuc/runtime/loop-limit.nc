%
O1000
#1 = 0
WHILE [#1 LT 1] DO 1
#2 = #2 + 1
END 1
M30
%
