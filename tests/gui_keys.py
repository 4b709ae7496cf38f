"""Presses keys on the X display in $DISPLAY through the XTest extension
(libXtst, ctypes only: no package beyond Python's standard library).
    gui_keys.py KEY [KEY...]      KEY: an X keysym name (space, s, q, Right)"""
import ctypes
import sys

x11 = ctypes.CDLL("libX11.so.6")
xtst = ctypes.CDLL("libXtst.so.6")
x11.XOpenDisplay.restype = ctypes.c_void_p
x11.XStringToKeysym.restype = ctypes.c_ulong
display = ctypes.c_void_p(x11.XOpenDisplay(None))
if not display.value:
    sys.exit("gui_keys.py: cannot open the display")
for name in sys.argv[1:]:
    code = x11.XKeysymToKeycode(display, ctypes.c_ulong(x11.XStringToKeysym(name.encode())))
    xtst.XTestFakeKeyEvent(display, code, True, 0)
    xtst.XTestFakeKeyEvent(display, code, False, 0)
    x11.XFlush(display)
x11.XCloseDisplay(display)
