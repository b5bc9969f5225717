O3101
(seed-000 comparison hole in feed per minute: F290.)
G21 G17 G90 G80 G94
G00 X0 Y0 Z45.
G98 G83 X10. Y5. Z-25. R22. Q7. F290.
G80
M30
