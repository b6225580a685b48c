/*
 * "Download for 3D printing": the view asks its host for the printable model of the current
 * triangle and hands the file to the browser. The host makes the bytes: in Jupyter the kernel
 * (trinormal.printmodel, through Explorer), on the site the same rule ported to JavaScript
 * (trinormal-printmodel.js, through explorer-site.js). The protocol, over the model's custom
 * messages:
 *   view -> host  { print: { marks: "letters" | "braille", seq } }
 *   host -> view  { printed: { seq, name, error, done } } and, when made, one buffer: the STL
 *   bytes (`done`: the sentence saying so).
 * A refusal (a degenerate triangle, one too thin for its features) comes back as the
 * package's sentence, shown in the status line beside the buttons.
 */
import { saveBlob, setText } from "./dom.js";

/**
 * Listen for the host's answers; returns { request(marks, status), stop() }. `status`: the
 * element that says what happened (a live region).
 */
export function createPrinting(model) {
  let seq = 0;
  let status = null;
  function onMessage(content, buffers) {
    const answer = content && content.printed;
    if (!answer || answer.seq !== seq || !status) return;
    if (answer.error) {
      setText(status, answer.error);
      return;
    }
    const data = buffers && buffers[0];
    if (!data) return;
    const bytes = data instanceof DataView ? new Uint8Array(data.buffer, data.byteOffset, data.byteLength) : new Uint8Array(data);
    saveBlob(new Blob([bytes], { type: "model/stl" }), answer.name, status.ownerDocument || document);
    setText(status, answer.done || "");
  }
  model.on("msg:custom", onMessage);
  return {
    request(marks, where) {
      seq += 1;
      status = where;
      setText(status, "");
      model.send({ print: { marks, seq } });
    },
    stop: () => model.off("msg:custom", onMessage),
  };
}
