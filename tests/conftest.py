# The pbrlab plugin itself (fixtures gl_context and golden, --update-goldens, the report
# header) is loaded through its pytest11 entry point; pytester runs it in the harness's
# own tests (tests/checking/test_plugin.py).
pytest_plugins = ["pytester"]
