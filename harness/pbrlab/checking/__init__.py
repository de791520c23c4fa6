"""The checking layer: how the harness decides an image or a number is right. Comparison and
tolerances (``compare``), the golden store and its pytest plugin (``goldens``,
``pytest_plugin``), the scenes goldens are made from (``golden_scenes``, ``charts``,
``contact_sheets``), cross-checks against renderers pbrlab did not write (``pyrender``,
``sample_viewer``, ``sample_viewer_prediction``), the Unity corpus (``unity_corpus``), the
hard-case catalogue (``hardcases``) and the machine-code scan (``codescan``)."""
