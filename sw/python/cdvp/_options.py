"""Python keywords as cdvp's command-line words."""

from ._errors import InputError


def value_text(value):
    """A value as the command line spells it: 5000, yes, sap,soa."""
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (list, tuple)):
        return ",".join(value_text(item) for item in value)
    text = str(value)
    if "\0" in text:  # a command-line word ends at its first NUL: the rest would be lost, not refused
        raise InputError(f"cdvp: {text!r}: a value may not hold a NUL character", 2)
    return text


def flag_words(options):
    """{"objects": 500, "quantum_ns": 100, "baseline": ["sap", "soa"], "ignore_capacity": True}
    -> ["--objects", "500", "--quantum-ns", "100", "--baseline", "sap,soa", "--ignore-capacity"].
    True is a switch, False and None leave the flag out, a list is comma-separated."""
    words = []
    for name, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + name.replace("_", "-")
        words += [flag] if value is True else [flag, value_text(value)]
    return words


def setting_words(settings):
    """{"bus.interrupt_ns": 5000} -> ["-c", "bus.interrupt_ns=5000"]."""
    words = []
    for name, value in (settings or {}).items():
        words += ["-c", f"{name}={value_text(value)}"]
    return words
