angle increment: 20
initial line width: 0.1
