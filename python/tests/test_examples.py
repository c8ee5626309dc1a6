"""The examples (python/examples/) write where no committed file is: a trial run of
fit_and_taylor.py without arguments went over docs/figures/python/fit_and_taylor.png, before."""
import importlib.util
import os
import subprocess

import pytest

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples")
SOURCE = os.path.normpath(os.path.join(EXAMPLES, "..", ".."))


def example(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(EXAMPLES, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def committed(directory):
    """Files of the repository under `directory` (git ls-files), or None without git."""
    try:
        done = subprocess.run(["git", "-C", SOURCE, "ls-files", "--", directory],
                              capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    return done.stdout.split()


def test_fit_and_taylor_writes_its_figure_outside_the_committed_ones():
    module = example("fit_and_taylor")
    default = module.output_directory([])
    assert default == os.path.join("out", "python")
    assert module.output_directory(["docs/figures/python"]) == "docs/figures/python"
    files = committed(default)
    if files is None:
        pytest.skip("no git checkout: what is committed cannot be listed")
    assert files == [] and committed(os.path.join("docs", "figures", "python")) == [
        "docs/figures/python/fit_and_taylor.png"]
