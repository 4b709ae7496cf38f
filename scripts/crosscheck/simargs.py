"""Argument checks shared by the cross-check simulators (standard library only)."""


def area(ap, text, example):
    """W x H in metres from 'WxH', or argparse's error naming --area."""
    try:
        w, h = (float(v) for v in text.split("x"))
    except ValueError:
        ap.error(f"--area must be W x H in metres, e.g. {example}, not '{text}'")
    return w, h


def positive(ap, args, names):
    """argparse's error for the first of `names` that is not above zero."""
    for name in names:
        if not getattr(args, name) > 0:
            ap.error(f"--{name.replace('_', '-')} must be positive")
