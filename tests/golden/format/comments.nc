O1201 (MAIN PROGRAM)
(G00 X99. Y99.)
G90 G01 X10. (move x to 10, lower case ok) Y5. F100
(#101=5)
M30
