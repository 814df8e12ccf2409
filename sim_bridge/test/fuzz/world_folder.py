"""A fuzzed world and the model files it includes, written to a temporary folder whose
``models`` folder is on GAZEBO_MODEL_PATH while in use (shared by the SDF fuzz test and the
spawn worker)."""
import contextlib
import os
import shutil
import tempfile


@contextlib.contextmanager
def written_world(text, files, prefix, keep_model_path):
    """Yields (folder, world file). ``keep_model_path``: the folder's models come first and
    the path as it was stays after them; otherwise they are the only ones."""
    folder = tempfile.mkdtemp(prefix=prefix)
    saved = os.environ.get("GAZEBO_MODEL_PATH")
    try:
        for relative, content in files.items():
            path = os.path.join(folder, relative)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8", errors="surrogatepass") as stream:
                stream.write(content)
        world_file = os.path.join(folder, "fuzz.world")
        with open(world_file, "w", encoding="utf-8", errors="surrogatepass") as stream:
            stream.write(text)
        models = [os.path.join(folder, "models")]
        if keep_model_path and saved:
            models.append(saved)
        os.environ["GAZEBO_MODEL_PATH"] = os.pathsep.join(models)
        yield folder, world_file
    finally:
        if saved is None:
            os.environ.pop("GAZEBO_MODEL_PATH", None)
        else:
            os.environ["GAZEBO_MODEL_PATH"] = saved
        shutil.rmtree(folder, ignore_errors=True)
