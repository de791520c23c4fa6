"""The commands layer: the `pbrlab` command (``cli``) and one module per subcommand, each with
``register(subparsers, common)``; also `python -m pbrlab`."""
