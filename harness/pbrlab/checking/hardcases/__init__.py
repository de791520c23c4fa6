"""Issue 5, hard cases stay numerically stable: the catalogue of edge cases of every public
GLSL function (catalogue), the argument kinds and adversarial floats (domains), the runner of
the catalogue and of the 10^6-sample sweeps through the GPU evaluator (run), and the half
precision study (half). `pbrlab hardcases` prints the catalogue's results; tests/checking/hardcases/
runs all of it."""
