initial line width: 0.1
