# Configuration for `jupyter nbconvert --execute` on these notebooks
# (make test, make notebook-check): `jupyter nbconvert --config
# notebooks/nbconvert_config.py --to notebook --execute NOTEBOOK`.
#
# Debian 12 packages ipywidgets 6, whose widgets open their comm without
# the 'state' field that the packaged nbclient (0.7) reads from every widget
# comm: executing a notebook that shows a slider then fails with
# KeyError: 'state' (the same mismatch Drake met on Ubuntu 22.04). Such a
# widget has no state to record headlessly anyway: skip it, keep everything
# else nbclient does. Where both are recent the check never triggers.
try:
    import nbclient.client
except ImportError:  # nbconvert 5 (Ubuntu 20.04) executes without nbclient
    nbclient = None

if nbclient is not None:
    _open_widget = nbclient.client.NotebookClient.on_comm_open_jupyter_widget

    def _open_widget_with_state(self, msg):
        if "state" not in msg["content"].get("data", {}):
            return None
        return _open_widget(self, msg)

    nbclient.client.NotebookClient.on_comm_open_jupyter_widget = _open_widget_with_state

c = get_config()  # noqa: F821 (given by traitlets when it loads this file)
c.ExecutePreprocessor.timeout = 300
