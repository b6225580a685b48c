/*
 * Listen to the normal: a short tone for U, then V, then N, whose pan follows the vector's x
 * (left to right), its pitch y (an octave down to an octave up) and its brightness and volume
 * z (dull and soft pointing down, bright and loud pointing up). Flip the winding and N's tone
 * jumps to the other side, the other octave, the other brightness: the right-hand rule turned
 * over, heard. Web Audio, started only by the Listen button (a user gesture); off by default.
 *
 * toneOf is a plain function (Node runs it in tests/test_describe.py); the rest needs a browser.
 */
import { element, setAttr } from "./dom.js";

// one tone: the gap before the next, in seconds; N's tone is longer, the answer after the two edges
const TONE = 0.32;
const N_TONE = 0.55;
const GAP = 0.12;
const BASE_HZ = 440; // pitch at y = 0; y = ±1 is an octave up or down
const CUTOFF_HZ = [400, 6400]; // the low-pass filter's cutoff at z = -1 and z = +1
const GAIN = [0.08, 0.2]; // volume at z = -1 and z = +1

/** A vector's direction ([x, y, z], any size, finite or not), or null when it has none. */
function direction(vector) {
  if (!Array.isArray(vector) || vector.length !== 3) return null;
  const m = Math.max(...vector.map((x) => Math.abs(Number(x))));
  if (!(m > 0)) return null;
  // ±infinity (a value beyond the float range) counts as the largest component
  const s = vector.map((x) => (Number.isFinite(m) ? Number(x) / m : Math.abs(x) === Infinity ? Math.sign(x) : 0));
  const length = Math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  return s.map((x) => x / length);
}

/** The tone of a vector: { pan, frequency, cutoff, gain }, or null for the zero vector. */
export function toneOf(vector) {
  const d = direction(vector);
  if (!d) return null;
  const [x, y, z] = d;
  const up = (z + 1) / 2; // 0 pointing straight down, 1 straight up
  return {
    pan: x,
    frequency: BASE_HZ * 2 ** y,
    cutoff: CUTOFF_HZ[0] * (CUTOFF_HZ[1] / CUTOFF_HZ[0]) ** up,
    gain: GAIN[0] + (GAIN[1] - GAIN[0]) * up,
  };
}

/** The tones of a state ({ u, v, unit_normal }): U, V and N in order (N missing when degenerate). */
export function tonesOf(state) {
  const st = state || {};
  return [
    ["U", toneOf(st.u), TONE],
    ["V", toneOf(st.v), TONE],
    ["N", toneOf(st.unit_normal), N_TONE],
  ].filter(([, tone]) => tone);
}

/** Play `tones` ([name, tone, seconds]) one after the other on `context`, from now; returns the oscillators. */
function play(context, tones) {
  const started = [];
  let t = context.currentTime + 0.02;
  for (const [, tone, seconds] of tones) {
    const osc = context.createOscillator();
    osc.type = "sawtooth";
    osc.frequency.setValueAtTime(tone.frequency, t);
    const filter = context.createBiquadFilter();
    filter.type = "lowpass";
    filter.frequency.setValueAtTime(tone.cutoff, t);
    const gain = context.createGain();
    gain.gain.setValueAtTime(0, t);
    gain.gain.linearRampToValueAtTime(tone.gain, t + 0.02);
    gain.gain.setValueAtTime(tone.gain, t + seconds - 0.06);
    gain.gain.linearRampToValueAtTime(0, t + seconds);
    const pan = context.createStereoPanner();
    pan.pan.setValueAtTime(tone.pan, t);
    osc.connect(filter).connect(gain).connect(pan).connect(context.destination);
    osc.start(t);
    osc.stop(t + seconds);
    started.push(osc);
    t += seconds + GAP;
  }
  return started;
}

/**
 * The Listen button, added to `bar`: pressed, it plays U, V and N one after another, and again
 * after every change of the triangle (`changed()`, called when the description settles);
 * pressed again, it is quiet. state(): the host's state. Returns { changed(), dispose() }.
 */
export function createListen(bar, state) {
  const button = element("button", "tnx-listen tn-text-button", "♪ Listen");
  button.type = "button";
  const label = "Listen to U, V and N: pan follows x, pitch follows y, brightness follows z";
  button.setAttribute("aria-label", label);
  button.title = label;
  setAttr(button, "aria-pressed", false);
  bar.appendChild(button);
  let context = null;
  let on = false;
  let playing = []; // the oscillators of the last sequence: a new one cuts it short

  function sound() {
    if (!on) return;
    const Context = window.AudioContext || window.webkitAudioContext;
    if (!Context) return;
    if (!context) context = new Context();
    if (context.state === "suspended") context.resume();
    for (const osc of playing) osc.stop();
    playing = play(context, tonesOf(state()));
  }

  button.addEventListener("click", () => {
    on = !on;
    setAttr(button, "aria-pressed", on);
    if (on) sound();
    else if (context) context.suspend();
  });

  return {
    changed: sound,
    dispose() {
      button.remove();
      if (context) context.close();
    },
  };
}
