angle increment: 25.7
/* ABOP draws these plants with thin lines, so the width is in pixels */
initial line width: 2 pixels
