"""Time in the harness: seconds as floats everywhere (Python's own convention, as time.sleep
and socket timeouts take it). The request messages count milliseconds or microseconds; these
helpers convert, refuse what is not a whole number of the message's unit, and carry the old
spellings (`ms=`, `late_ms=`, `now_ns()`, ...) as deprecated aliases that warn."""

import warnings


def whole(seconds, per_second, name):
    """`seconds` in units of 1/per_second (1000: ms, 1000000: µs) as an int; ValueError when
    it is negative or not a whole number of them (e.g. 0.0005 s as ms)."""
    count = round(seconds * per_second)
    if count < 0 or abs(count - seconds * per_second) > 1e-6:
        unit = {1000: "ms", 1000000: "µs"}.get(per_second, f"1/{per_second} s")
        raise ValueError(f"{name}={seconds!r} s is not a whole number of {unit} (≥ 0)")
    return count


def renamed(value, old_value, old_name, new_name, per_second, default=None, stacklevel=3):
    """The value in seconds of a parameter whose old spelling `old_name` counted in
    1/per_second units: old_value is converted with a DeprecationWarning; both given must
    agree (TypeError otherwise). `value` None means not given (then `default`)."""
    if old_value is None:
        return default if value is None else value
    warnings.warn(f"{old_name}= is deprecated: use {new_name}= in seconds "
                  f"({new_name}={old_value / per_second:g})", DeprecationWarning,
                  stacklevel=stacklevel)
    converted = old_value / per_second
    if value is not None and abs(value - converted) > 1e-9:
        raise TypeError(f"{old_name}={old_value} (the deprecated spelling of {new_name}) "
                        f"differs from {new_name}={value}; give {new_name} only")
    return converted


def deprecated(old, new, stacklevel=3):
    """A DeprecationWarning: `old` is the old spelling of `new`."""
    warnings.warn(f"{old} is deprecated: use {new}", DeprecationWarning, stacklevel=stacklevel)
