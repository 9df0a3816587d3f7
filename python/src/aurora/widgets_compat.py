"""Widgets in notebooks that `jupyter nbconvert --execute` runs, on Debian 12.

Debian 12 packages ipywidgets 6, whose widgets open their comm with the
widget's state as the message's data itself; the packaged nbclient (0.7),
which `jupyter nbconvert --execute` runs, reads `data['state']` from every
widget's comm_open (ipywidgets 7's layout) and fails with KeyError: 'state'
on the first slider (the mismatch Drake met on Ubuntu 22.04). We send the
state under 'state' as well, keeping the flat keys that ipywidgets 6's own
front end reads, so a notebook with sliders executes with plain
`jupyter nbconvert --execute` and still works in the browser. Applied by
`import aurora` inside a kernel; nothing changes with ipywidgets 7 or later
or outside a kernel."""
import sys


def old_ipywidgets():
    """ipywidgets before 7 (Debian 12's 6, Ubuntu 20.04's 6) is installed."""
    try:
        import ipywidgets
    except ImportError:
        return False
    return int(ipywidgets.__version__.split(".")[0]) < 7


def apply():
    if "ipykernel" not in sys.modules or not old_ipywidgets():
        return
    from ipywidgets.widgets import widget
    if getattr(widget.Widget.open, "aurora", False):
        return

    def open_with_state(self):
        """ipywidgets 6's Widget.open, with the state also under 'state'."""
        if self.comm is None:
            state, _, buffers = self._split_state_buffers(self.get_state())
            args = dict(target_name="jupyter.widget", data=dict(state, state=dict(state)))
            if self._model_id is not None:
                args["comm_id"] = self._model_id
            self.comm = widget.Comm(**args)
            if buffers:
                self.send_state()  # ipywidgets 6: binary state goes in a second message

    open_with_state.aurora = True
    widget.Widget.open = open_with_state
