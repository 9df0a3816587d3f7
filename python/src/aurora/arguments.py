"""The checks of the Python entry points' arguments (aurora.simulate,
simulate_formation, sweep, read_bag): numpy values are taken as the plain
Python values they hold; anything else that is not what the argument takes
raises ValueError naming the argument, what it got and what it accepts.

The YAML readers (PyYAML's safe_dump, the C++ readers behind it) know
only plain values, so a dict is made plain before it is written."""
import numbers

from aurora._core import MAX_DELAY_SAMPLES  # the history a delay may need (aurora_control/params/limits.h)


def _numpy():
    try:
        import numpy
        return numpy
    except ImportError:  # numpy is optional for the plain API
        return None


def plain(value, name):
    """`value` with numpy scalars and arrays turned into Python numbers and
    lists, tuples into lists; other types raise ValueError naming the key."""
    np = _numpy()
    if np is not None and isinstance(value, np.ndarray):
        return [plain(v, "%s[%d]" % (name, i)) for i, v in enumerate(value.tolist())]
    if np is not None and isinstance(value, np.generic):
        return value.item()
    if isinstance(value, dict):
        out = {}
        for k, v in value.items():
            if not isinstance(k, str):
                raise ValueError("%s: keys must be words, got %r" % (name, k))
            out[k] = plain(v, "%s.%s" % (name, k) if name else k)
        return out
    if isinstance(value, (list, tuple)):
        return [plain(v, "%s[%d]" % (name, i)) for i, v in enumerate(value)]
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    raise ValueError("%s: %r (%s) is not a YAML value: give numbers, words, lists or dicts"
                     % (name, value, type(value).__name__))


def whole(value, name, low=0, high=MAX_DELAY_SAMPLES, what="whole samples", accepted="integer samples"):
    """An int (a Python or numpy integer) in [low, high]."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ValueError("%s: expected %s (an int in [%d, %d], e.g. %s=3), got %r" % (name, what, low, high, name, value))
    value = int(value)
    if not low <= value <= high:
        raise ValueError("%s = %d is refused: accepted %s in [%d, %d]" % (name, value, accepted, low, high))
    return value


def positive(value, name):
    """A real number above 0 (a Python or numpy int or float, not a bool)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not value > 0:
        raise ValueError("%s: expected a number above 0, got %r" % (name, value))
    return float(value)


def boolean(value, name):
    """True or False (a Python or numpy bool); "no", 0 and the like are refused."""
    np = _numpy()
    if isinstance(value, bool) or (np is not None and isinstance(value, np.bool_)):
        return bool(value)
    raise ValueError("%s: expected True or False, got %r" % (name, value))


def per_drone(values, name, drones=2, robot="drone"):
    """One whole number of samples per drone (or `robot`), in their order: a
    list, a tuple or a 1-D numpy array (a dict or a set has no order)."""
    np = _numpy()
    if np is not None and isinstance(values, np.ndarray):
        values = values.tolist()
    if not isinstance(values, (list, tuple)):
        raise ValueError("%s: expected a list of one delay per %s in the formation's order, e.g. %s=(3, 9), "
                         "got %r" % (name, robot, name, values))
    if len(values) != drones:
        raise ValueError("%s: expected one delay per %s (%d), got %d: %r" % (name, robot, drones, len(values), values))
    return [whole(v, "%s[%d] (%s %d)" % (name, i, robot, i + 1)) for i, v in enumerate(values)]
