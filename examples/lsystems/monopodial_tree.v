angle increment: 45
/* ABOP figure 2.6 is a line drawing, so the !(w) widths are pixels (w0 = 10) */
initial line width: 10 pixels
line width increment: 1
