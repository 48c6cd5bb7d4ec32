initial line width: 0.05
