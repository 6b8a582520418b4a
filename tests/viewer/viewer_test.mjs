// The step-through viewer in a real browser (docs/viewer.md): Debian's Chromium, headless,
// driven through the DevTools protocol over --remote-debugging-pipe (node's own modules only;
// nothing is downloaded). Checks, on a page `lamina run` wrote with a trace of the same run:
//   - no console error and no uncaught exception while the page is used;
//   - → three times shows step 3, and the bodies at t + Δt shown are trace line 3's state, exactly
//     (the trace is written by the trace writer, not the viewer: an independent record);
//   - ↑/↓ move through the sweeps and each λ shown is the engine's record after that sweep; the
//     last sweep's λ is what `lamina run --explain 3 --explain-format json` solved (another
//     path through the engine);
//   - a deep link #step=40&sweep=3 opens at step 40, sweep 3;
//   - a screenshot is not blank (many colours, the frame loaded).
// usage: node viewer_test.mjs <chromium> <lamina> <page folder> <trace.jsonl> <scene>
//        node viewer_test.mjs --pages <chromium> <page folder>...
//          (every tutorial's page: each of its scenes opens, its first steps and sweeps are shown
//           with no console error; a page written with --lang ko shows no English of its own)
import { spawn, execFileSync } from "node:child_process";
import { readFileSync, writeFileSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import assert from "node:assert/strict";
import { inflateSync } from "node:zlib";

const pagesOnly = process.argv[2] === "--pages";
const [chromium, lamina, folder, tracePath, scene] = process.argv.slice(pagesOnly ? 3 : 2);
const pageFolders = pagesOnly ? process.argv.slice(4) : [];
const profile = mkdtempSync(join(tmpdir(), "lamina-viewer-chromium-"));
const browser = spawn(chromium, [
  "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
  "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage", `--user-data-dir=${profile}`,
  "--remote-debugging-pipe", "--window-size=1500,1100", "about:blank",
], { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
let browserLog = "";
browser.stderr.on("data", (d) => { browserLog += d; });

// The protocol: JSON messages ended by a NUL byte, written to fd 3, read from fd 4.
let nextId = 1;
const waiting = new Map();
const listeners = [];
let pending = "";
browser.stdio[4].on("data", (chunk) => {
  pending += chunk.toString("utf8");
  let end;
  while ((end = pending.indexOf("\0")) >= 0) {
    const message = JSON.parse(pending.slice(0, end));
    pending = pending.slice(end + 1);
    if (message.id && waiting.has(message.id)) {
      const { resolve, reject } = waiting.get(message.id);
      waiting.delete(message.id);
      if (message.error) reject(new Error(JSON.stringify(message.error))); else resolve(message.result);
    } else {
      if (process.env.CDP_DEBUG) console.log("event", message.method, JSON.stringify(message.params).slice(0, 200));
      for (const listen of [...listeners]) listen(message);
    }
  }
});
function send(method, params = {}, sessionId) {
  const id = nextId++;
  browser.stdio[3].write(JSON.stringify({ id, method, params, ...(sessionId ? { sessionId } : {}) }) + "\0");
  return new Promise((resolve, reject) => waiting.set(id, { resolve, reject }));
}
function once(method, timeout = 60000) {
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no ${method} in ${timeout} ms`)), timeout);
    const listen = (m) => {
      if (m.method !== method) return;
      clearTimeout(timer);
      listeners.splice(listeners.indexOf(listen), 1);
      resolve(m.params);
    };
    listeners.push(listen);
  });
}

const errors = [];
listeners.push((m) => {
  if (m.method === "Runtime.exceptionThrown") errors.push("exception: " + JSON.stringify(m.params.exceptionDetails.exception?.description ?? m.params.exceptionDetails.text));
  if (m.method === "Runtime.consoleAPICalled" && (m.params.type === "error" || m.params.type === "assert")) errors.push("console.error: " + JSON.stringify(m.params.args));
  if (m.method === "Log.entryAdded" && m.params.entry.level === "error") errors.push("log: " + m.params.entry.text + " " + (m.params.entry.url ?? ""));
});

let session;
async function evaluate(expression) {
  const r = await send("Runtime.evaluate", { expression, returnByValue: true, awaitPromise: true }, session);
  if (r.exceptionDetails) throw new Error(`${expression}: ${JSON.stringify(r.exceptionDetails)}`);
  return r.result.value;
}
async function key(name, code) {
  for (const type of ["keyDown", "keyUp"]) {
    await send("Input.dispatchKeyEvent", { type, key: name, code: name, windowsVirtualKeyCode: code, nativeVirtualKeyCode: code }, session);
  }
}
// Waits until the frame image of the step shown has loaded, or failed to (its naturalWidth then
// stays 0, which the checks report): a step changed by a key loads its frame after the key.
const frameSettled = () => evaluate(`new Promise((done) => { const img = document.getElementById("frame");
    if (img.complete && img.naturalWidth) done(); else { img.onload = () => done(); img.onerror = () => done(); } })`);
async function open(url) {
  const loaded = once("Page.loadEventFired");
  await send("Page.navigate", { url }, session);
  await loaded;
  if (url === "about:blank") return;
  await frameSettled();
}
// What the page shows: the step, the sweep, each row's λ, the bodies at t + Δt (full precision
// from the cells' data-value).
const shown = () => evaluate(`(() => ({
  step: Number(document.getElementById("step-number").dataset.step),
  sweep: document.getElementById("sweep-number") ? Number(document.getElementById("sweep-number").dataset.sweep) : null,
  lambdas: [...document.querySelectorAll("#rows td.lambda")].map((td) => Number(td.dataset.value)),
  after: [...document.querySelectorAll('#bodies tr[data-when="t+dt"]')].map((tr) =>
    ({ body: Number(tr.dataset.body), values: [...tr.querySelectorAll("td[data-value]")].map((td) => Number(td.dataset.value)) })),
  frame: document.getElementById("frame").naturalWidth,
}))()`);

// Counts distinct colours in a PNG screenshot (8-bit RGB or RGBA, no interlace): a blank page
// has a handful.
function distinctColours(png) {
  let offset = 8, width = 0, height = 0, channels = 0;
  const data = [];
  while (offset < png.length) {
    const length = png.readUInt32BE(offset), type = png.toString("ascii", offset + 4, offset + 8);
    const body = png.subarray(offset + 8, offset + 8 + length);
    if (type === "IHDR") { width = body.readUInt32BE(0); height = body.readUInt32BE(4); channels = body[9] === 6 ? 4 : 3; assert.equal(body[8], 8); }
    if (type === "IDAT") data.push(body);
    offset += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(data)), stride = width * channels, colours = new Set();
  let previous = Buffer.alloc(stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)], line = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? line[x - channels] : 0, b = previous[x], c = x >= channels ? previous[x - channels] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      line[x] = (line[x] + [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter]) & 255;
    }
    for (let x = 0; x < stride; x += channels * 7) colours.add(line.readUIntBE(x, 3));
    previous = line;
  }
  return colours.size;
}

try {
  const version = await send("Browser.getVersion");
  console.log(`browser: ${version.product}`);
  const { targetId } = await send("Target.createTarget", { url: "about:blank" });
  ({ sessionId: session } = await send("Target.attachToTarget", { targetId, flatten: true }));
  await send("Page.enable", {}, session);
  await send("Runtime.enable", {}, session);
  await send("Log.enable", {}, session);

  if (pagesOnly) {
    for (const pageFolder of pageFolders) {
      const url = pathToFileURL(join(pageFolder, "index.html")).href;
      const runs = JSON.parse(readFileSync(join(pageFolder, "data.js"), "utf8").replace(/^window\.LAMINA_VIEWER = /, "").replace(/;\s*$/, "")).runs;
      for (let r = 0; r < runs.length; ++r) {
        await open("about:blank");
        await open(`${url}#run=${r}`);
        for (let i = 0; i < 3; ++i) { await key("ArrowRight", 39); await key("ArrowUp", 38); await key("ArrowDown", 40); }
        await frameSettled();
        const now = await shown();
        assert.equal(now.step, Math.min(3, runs[r].steps - 1), `${pageFolder} run ${r} (${runs[r].scene}): → three times`);
        assert.ok(now.frame > 0, `${pageFolder} run ${r}: the frame loaded`);
      }
      const lang = JSON.parse(readFileSync(join(pageFolder, "data.js"), "utf8").replace(/^window\.LAMINA_VIEWER = /, "").replace(/;\s*$/, "")).lang;
      if (lang === "ko") {
        // a Korean page: its own words (headings, table heads, readouts, notes) have no English
        // left but names (the scene's, its bodies', the method's), a code name (World::step), a
        // file (docs/….md) and the words the frames keep too (language.h, english_words)
        // and the equations' statements, but for their formulas (code)
        const text = await evaluate(`[...document.querySelectorAll("h1, h2, th, summary, #keys, #readout, #sweep-readout, #energy, .empty, .note, #equation-list .entry")]
          .map((e) => { const c = e.cloneNode(true); c.querySelectorAll("code").forEach((code) => code.remove()); return c.textContent; }).join("\\n")`);
        const kept = new Set(["Lamina", "MLCP", "exp", ...runs.flatMap((r) => [r.scene, r.program, ...r.bodies]),
                              ...runs.flatMap((r) => r.detail_of.map((d) => d.method))]);
        const english = (text.replace(/\S+\.md|\w+::\w+/g, "").match(/(?<!\w)[A-Za-z][A-Za-z0-9-]+/g) || []).filter((w) => !kept.has(w));
        assert.deepEqual(english, [], `${pageFolder}: English left on the Korean page`);
        assert.equal(await evaluate("document.documentElement.lang"), "ko", `${pageFolder}: <html lang="ko">`);
      }
      console.log(`${pageFolder}: ${runs.length} scenes shown${lang === "ko" ? ", in Korean" : ""}`);
    }
    assert.deepEqual(errors, [], "no console errors");
    process.exitCode = 0;
  } else {
  const page = pathToFileURL(join(folder, "index.html")).href;
  const data = JSON.parse(readFileSync(join(folder, "data.js"), "utf8").replace(/^window\.LAMINA_VIEWER = /, "").replace(/;\s*$/, ""));
  const run = data.runs[0];
  const trace = readFileSync(tracePath, "utf8").trim().split("\n").map((line) => JSON.parse(line));

  // → three times: step 3, whose bodies at t + Δt are trace line 3's
  await open(page);
  assert.equal((await shown()).step, 0, "the page opens at step 0");
  for (let i = 0; i < 3; ++i) await key("ArrowRight", 39);
  let now = await shown();
  assert.equal(now.step, 3, "→ three times shows step 3");
  assert.equal(trace[3].step, 3);
  for (const traced of trace[3].bodies) {
    const b = run.bodies.indexOf(traced.name);
    const row = now.after.find((r) => r.body === b);
    assert.ok(row, `body ${traced.name} is shown`);
    // x, y, θ, v_x, v_y, ω at t + Δt: the same doubles as the trace's
    assert.deepEqual(row.values.slice(0, 6), [...traced.position, traced.angle, ...traced.velocity, traced.angular_velocity],
                     `step 3: ${traced.name} at t + Δt is trace line 3's state`);
  }

  // ↑/↓ through the sweeps of a step with rows (the first detailed step with contacts)
  const k = run.detail_of.findIndex((d) => d.rows.length > 0 && d.residuals.length > 1) + run.detail[0];
  assert.ok(k >= run.detail[0], "some step solves rows by sweeps");
  const detail = run.detail_of[k - run.detail[0]];
  for (let i = 3; i < k; ++i) await key("ArrowRight", 39);
  now = await shown();
  assert.equal(now.step, k);
  const sweeps = detail.residuals.length;
  assert.equal(now.sweep, sweeps, "a step opens at its last sweep");
  const explained = JSON.parse(execFileSync(lamina, ["run", scene, "--solver", "pgs", "--explain", String(k), "--explain-format", "json"], { encoding: "utf8" }));
  const solved = explained.sections.filter((s) => s.title.startsWith("row ")).map((s) => s.quantities.find((q) => q.symbol === "λ").value);
  assert.deepEqual(now.lambdas, solved, `step ${k}: the last sweep's λ is what --explain ${k} solved`);
  for (let s = sweeps - 1; s >= 0; --s) {
    await key("ArrowDown", 40);
    now = await shown();
    assert.equal(now.sweep, s, "↓ goes back one sweep");
    assert.deepEqual(now.lambdas, detail.rows.map((r) => (s === 0 ? r.lexp : r.sweeps[s - 1])), `λ after sweep ${s} is the engine's record`);
  }
  await key("ArrowUp", 38);
  assert.equal((await shown()).sweep, 1, "↑ goes on one sweep");

  // a deep link, opened afresh (from another page: a new hash alone would not load the page)
  await open("about:blank");
  await open(page + "#step=40&sweep=3");
  now = await shown();
  assert.equal(now.step, 40, "#step=40 opens step 40");
  assert.equal(now.sweep, 3, "&sweep=3 opens sweep 3");
  assert.deepEqual(now.lambdas, run.detail_of[40 - run.detail[0]].rows.map((r) => r.sweeps[2]));

  // a screenshot that is not blank
  const shot = Buffer.from((await send("Page.captureScreenshot", { format: "png" }, session)).data, "base64");
  writeFileSync(join(folder, "screenshot.png"), shot);
  assert.ok(now.frame > 0, "the frame image loaded");
  const colours = distinctColours(shot);
  assert.ok(colours >= 50, `the screenshot has ${colours} colours (a blank page has a few)`);

  assert.deepEqual(errors, [], "no console errors");
  console.log(`viewer: all checks passed (step ${k}: ${sweeps} sweeps, ${detail.rows.length} rows; screenshot ${colours} colours)`);
  process.exitCode = 0;
  }
} catch (e) {
  console.error(`FAIL: ${e.message}`);
  if (errors.length) console.error("page errors: " + errors.join("\n"));
  process.exitCode = 1;
} finally {
  // close the browser and wait for it, so that its profile can go
  const exited = new Promise((done) => browser.on("exit", done));
  send("Browser.close").catch(() => {});
  const timer = setTimeout(() => browser.kill("SIGKILL"), 5000);
  await exited;
  clearTimeout(timer);
  try { rmSync(profile, { recursive: true, force: true, maxRetries: 5 }); } catch { /* a temporary folder */ }
}
