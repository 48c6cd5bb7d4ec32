angle increment: 45
initial line width: 10
line width increment: 1
