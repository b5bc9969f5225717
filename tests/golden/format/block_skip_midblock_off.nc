O1703
(A CAM post writes the coolant behind a slash: G43 H6 Z.25 /M8)
G90 G00 X0 Y0 Z50.
G43 H1 Z25. /M08
G01 X10. F100 /Y20.
#101=#4001
G00 X20. /3 Y30.
M30
