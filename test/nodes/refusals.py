"""Shared by the Python checks: bad input refused with ValueError and the
tools' message."""


def expect_refusals(test, cases):
    """Each (call, text) of `cases`: the call raises ValueError whose message holds text."""
    for call, text in cases:
        with test.assertRaises(ValueError) as e:
            call()
        test.assertIn(text, str(e.exception))
