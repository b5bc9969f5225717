O3001
(seed-000 comparison hole: drill D3 x 45 from surface Z20, G83 Q7)
G21 G17 G90 G80 G95
G00 X0 Y0 Z45.
M03 S2900
G98 G83 X10. Y5. Z-25. R22. Q7. F0.1
G80
M30
