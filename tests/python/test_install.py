"""`cmake --install` puts a self-contained package under the prefix: it
imports from there and builds twins from its own copy of the models."""
import os
import pathlib
import subprocess
import sys

import pytest

from conftest import BUILD_DIR


@pytest.mark.skipif(not (BUILD_DIR / "cmake_install.cmake").exists(), reason="no CMake build folder")
def test_installed_package_stands_alone(tmp_path):
    subprocess.run(["cmake", "--install", str(BUILD_DIR), "--prefix", str(tmp_path)],
                   check=True, capture_output=True)
    [package] = list(tmp_path.glob("lib/python3*/dist-packages/sreh_twin"))
    assert (package / "models" / "sreh50.xml").is_file() and (package / "__init__.pyi").is_file()
    code = ("import sreh_twin, pathlib;"
            "print(sreh_twin.models_dir());"
            "t = sreh_twin.Twin(load_file='models/loads/gripper.xml');"
            "print(t.load_inertia_gcm2 > 0, t.isdu_read(64, 4) > 0)")
    env = {k: v for k, v in os.environ.items() if k != "SREH_TWIN_MODELS_DIR"}
    env["PYTHONPATH"] = str(package.parent)
    done = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True,
                          check=True)
    models, loaded = done.stdout.splitlines()
    assert pathlib.Path(models) == package / "models"
    assert loaded == "True True"
