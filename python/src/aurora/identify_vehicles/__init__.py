"""The vehicles identify fits (docs/identify.md): one module each, named as
its vehicle file's `type` (bebop2.py for `type: bebop2`), giving MODEL, an
aurora.identify_model.Model. MODELS maps each type to its model; a vehicle
is added by adding its module here, nothing else."""
import importlib
import pkgutil

MODELS = {m.name: importlib.import_module(__name__ + "." + m.name).MODEL
          for m in pkgutil.iter_modules(__path__) if not m.name.startswith("_")}
