"""The types of the keyword arguments of :func:`cartan.solve`, :func:`cartan.solve_general` and the
problems of :func:`cartan.sweep`, checked before the compiled module sees them: a wrong type is a
TypeError naming the function, the argument, its value and what it must be, never pybind11's
signature of an internal function. The values are the library's to check (ValueError), apart from
integers beyond its 32-bit range (ValueError here: pybind11 would raise a TypeError)."""
import numbers

#: Real numbers (int or float, NumPy's included; not bool).
REAL = ("lam", "T", "tol", "lambda_start", "time_limit")
#: Integers (int or NumPy integers; not bool or float).
INTEGER = ("N", "order", "max_iterations", "segments", "samples", "max_nodes")
#: Words (str).
TEXT = ("method", "continuation")
#: Arguments whose None means "the default".
OPTIONAL = ("segments", "lambda_start", "samples", "max_nodes", "time_limit")


def check_type(where, key, value):
    """Raises TypeError "<where>: <key> = <value> (<type>) is not <what>" for a value of the wrong type."""
    if key in OPTIONAL and value is None:
        return
    integer = isinstance(value, numbers.Integral) and not isinstance(value, bool)
    real = isinstance(value, numbers.Real) and not isinstance(value, bool)
    if key in REAL and not real:
        raise TypeError(f"{where}: {key} = {value!r} ({type(value).__name__}) is not a real number")
    if key in INTEGER and not integer:
        raise TypeError(f"{where}: {key} = {value!r} ({type(value).__name__}) is not an integer")
    if key in INTEGER and not -2**31 <= value < 2**31:
        raise ValueError(f"{where}: {key} = {value} is out of range (the library's integers are below 2^31)")
    if key in TEXT and not isinstance(value, str):
        raise TypeError(f"{where}: {key} = {value!r} ({type(value).__name__}) is not a string")


def check_types(where, arguments):
    """check_type for every entry of the dict `arguments`."""
    for key, value in arguments.items():
        check_type(where, key, value)
