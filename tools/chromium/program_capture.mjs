// Records the WebGL2 programs a page links and draws with (issue 35: the peers' own fragment
// programs, compiled by pbrlab's bench for AMD families): wraps five methods of
// WebGL2RenderingContext.prototype in the page before its renderer makes a context.
//
//   await page.evaluate(installProgramCapture);      // before the page creates its context
//   ... the page renders ...
//   const programs = await page.evaluate(capturedPrograms);
//
// Each linked program: {index, vertex, fragment (the source text as passed to the
// implementation's shaderSource, i.e. after the page's own rewrites), draws (draw calls
// issued while it was current)}.
// The page's own hooks that replace gl.shaderSource on the instance bind the prototype's
// method, so they call through this wrapper and it sees their output.

export function installProgramCapture() {
  const proto = WebGL2RenderingContext.prototype;
  const sources = new WeakMap();   // shader -> {type, text}
  const attached = new WeakMap();  // program -> [shader, ...]
  const indexOf = new WeakMap();   // program -> index into programs (its latest link)
  const programs = [];
  let current = null;
  const wrap = (name, after) => {
    const original = proto[name];
    proto[name] = function (...args) {
      const result = original.apply(this, args);
      after.call(this, args, result);
      return result;
    };
  };
  wrap("createShader", function ([type], shader) { if (shader) sources.set(shader, { type, text: "" }); });
  wrap("shaderSource", function ([shader, text]) {
    const entry = sources.get(shader);
    if (entry) entry.text = text;
  });
  wrap("attachShader", function ([program, shader]) {
    if (!attached.has(program)) attached.set(program, []);
    attached.get(program).push(shader);
  });
  wrap("linkProgram", function ([program]) {
    const stages = (attached.get(program) || []).map((s) => sources.get(s)).filter(Boolean);
    const text = (type) => (stages.find((s) => s.type === type) || { text: null }).text;
    indexOf.set(program, programs.length);
    programs.push({ index: programs.length, vertex: text(this.VERTEX_SHADER), fragment: text(this.FRAGMENT_SHADER),
                    draws: 0 });
  });
  wrap("useProgram", function ([program]) { current = program && indexOf.has(program) ? programs[indexOf.get(program)] : null; });
  for (const name of ["drawArrays", "drawElements", "drawArraysInstanced", "drawElementsInstanced", "drawRangeElements"]) {
    wrap(name, function () {
      if (current) current.draws += 1;
    });
  }
  window.__pbrlabPrograms = programs;
}

export function capturedPrograms() {
  if (!window.__pbrlabPrograms) throw new Error("installProgramCapture did not run in this page");
  return window.__pbrlabPrograms;
}
