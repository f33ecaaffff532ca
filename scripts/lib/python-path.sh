# Sourced by the scripts: puts the checkout's Python/ (the project's package, Python/psivolume)
# first on PYTHONPATH for every pvpython, pvbatch and paraview they start. $root is the checkout.
export PYTHONPATH="$root/Python${PYTHONPATH:+:$PYTHONPATH}"
