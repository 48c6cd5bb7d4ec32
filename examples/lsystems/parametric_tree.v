angle increment: 85
/* ABOP draws this tree with thin lines, so the width is in pixels */
initial line width: 2 pixels
