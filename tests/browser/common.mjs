// What the browser tests share: Chromium headless (Debian's, CHROMIUM overrides its path),
// pages that collect their console errors and requests, and statistics of screenshots
// computed by the browser itself.
import { chromium } from "playwright-core";

const browserPath = process.env.CHROMIUM ?? "/usr/bin/chromium";
let browser;

export async function launch() {
  browser = await chromium.launch({
    executablePath: browserPath,
    args: ["--no-sandbox", "--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           "--disable-quic", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync"],
  });
  return browser;
}

// A new page with its console errors, uncaught exceptions and requests collected.
export async function openPage(width = 1200, height = 760) {
  const page = await browser.newPage({ viewport: { width, height } });
  const log = { errors: [], requests: [] };
  page.on("console", m => { if (m.type() === "error") log.errors.push(m.text()); });
  page.on("pageerror", e => log.errors.push(e.message));
  page.on("request", r => log.requests.push(r.url()));
  return { page, log };
}

// Pixels of PNG screenshots, decoded by the browser itself in a blank page, reduced there to
// statistics: `spread`, the fraction of pixels farther than 24 (sum of |dR|+|dG|+|dB|) from the
// most common colour, and `colours`, the number of distinct colours at 4 bits a channel.
let analyser;
export async function analyse(fn, ...pngs) {
  if (!analyser) analyser = (await openPage()).page;
  return analyser.evaluate(async ([source, b64s]) => {
    const images = [];
    for (const b64 of b64s) {
      const bitmap = await createImageBitmap(await (await fetch("data:image/png;base64," + b64)).blob());
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const ctx = canvas.getContext("2d");
      ctx.drawImage(bitmap, 0, 0);
      images.push(ctx.getImageData(0, 0, bitmap.width, bitmap.height));
    }
    return (0, eval)(source)(...images);
  }, [fn.toString(), pngs.map(p => p.toString("base64"))]);
}
export const pixelStats = img => {
  const count = new Map();
  for (let i = 0; i < img.data.length; i += 4) {
    const key = (img.data[i] >> 4) << 8 | (img.data[i + 1] >> 4) << 4 | img.data[i + 2] >> 4;
    count.set(key, (count.get(key) ?? 0) + 1);
  }
  let mode = 0, best = -1;
  for (let i = 0; i < img.data.length; i += 4) {
    const key = (img.data[i] >> 4) << 8 | (img.data[i + 1] >> 4) << 4 | img.data[i + 2] >> 4;
    if (count.get(key) > best) { best = count.get(key); mode = i; }
    if (best > img.data.length / 8) break;
  }
  let far = 0;
  for (let i = 0; i < img.data.length; i += 4) {
    const d = Math.abs(img.data[i] - img.data[mode]) + Math.abs(img.data[i + 1] - img.data[mode + 1])
            + Math.abs(img.data[i + 2] - img.data[mode + 2]);
    if (d > 24) far++;
  }
  return { spread: far / (img.data.length / 4), colours: count.size, width: img.width, height: img.height };
};
