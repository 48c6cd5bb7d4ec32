angle factor: 16
initial line width: 3 pixels
line style: cylinder
tropism direction: 0,-1,0
initial elasticity: 0.2
step: 0.5
