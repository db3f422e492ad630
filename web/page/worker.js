// Runs the WebAssembly module off the page's thread, so a long render never freezes the
// page (a newer request replaces this worker). Messages: {id, request} in; {id, status,
// text, width, height, rgba} out, first a `partial` one for each step of a view drawn in
// steps (status 3), then the answer.
let module = null;
const ready = fetch("tinyfractal_web.wasm")
  .then((response) => {
    if (!response.ok) throw new Error(`tinyfractal_web.wasm: HTTP ${response.status}`);
    return response.arrayBuffer();
  })
  .then((bytes) => WebAssembly.instantiate(bytes, {}))
  .then((result) => { module = result.instance.exports; });

function answer(request) {
  const bytes = new TextEncoder().encode(request);
  const at = module.input_buffer(bytes.length);
  new Uint8Array(module.memory.buffer, at, bytes.length).set(bytes);
  const status = module.run();
  const text = new TextDecoder().decode(
    new Uint8Array(module.memory.buffer, module.output_pointer(), module.output_length()));
  const width = module.picture_width(), height = module.picture_height();
  let rgba = null;
  if (status === 0 || status === 3) {
    rgba = new Uint8ClampedArray(module.memory.buffer, module.pixels_pointer(), width * height * 4).slice();
  }
  return { status, text, width, height, rgba };
}

onmessage = (event) => {
  ready
    .then(() => {
      let reply = answer(event.data.request);
      while (reply.status === 3) {
        postMessage({ id: event.data.id, partial: true, ...reply }, [reply.rgba.buffer]);
        reply = answer("more");
      }
      postMessage({ id: event.data.id, ...reply }, reply.rgba ? [reply.rgba.buffer] : []);
    })
    .catch((error) => postMessage({ id: event.data.id, status: 2, text: String(error) }));
};
