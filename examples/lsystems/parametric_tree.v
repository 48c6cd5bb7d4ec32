angle increment: 85
initial line width: 0.05
