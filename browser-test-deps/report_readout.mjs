// Opens a skylit HTML report in headless Chromium and prints, as one JSON line, what a
// person would get from it: each image's natural size once loaded, and the read-out with
// the mouse over each pixel (x, y) given, in every image that has one.
// tests/app/report_browser_test.cpp runs it and checks the numbers.
//
//   node report_readout.mjs CHROMIUM PAGE.html X Y [X Y …]
import { withPage } from './chromium_page.mjs';

const [executablePath, pagePath, ...coordinates] = process.argv.slice(2);
const result = await withPage(executablePath, pagePath, async (page, errors) => {
  const images = await page.$$eval('img', all => all.map(img => ({
    alt: img.alt, complete: img.complete, naturalWidth: img.naturalWidth, naturalHeight: img.naturalHeight })));
  const readouts = [];
  for (let i = 0; i + 1 < coordinates.length; i += 2) {
    const [x, y] = [Number(coordinates[i]), Number(coordinates[i + 1])];
    for (const handle of await page.$$('img.reads')) {
      await handle.scrollIntoViewIfNeeded();
      const box = await handle.boundingBox();
      const [width, height] = await handle.evaluate(img => [img.naturalWidth, img.naturalHeight]);
      // Chromium delivers whole CSS pixels to the page: the first whole one at or after
      // the pixel's left (top) edge lies inside it when the image is shown at least 1:1.
      await page.mouse.move(Math.ceil(box.x + x * box.width / width), Math.ceil(box.y + y * box.height / height));
      readouts.push(await page.$eval('#readout', p => ({ text: p.textContent, ...p.dataset })));
    }
  }
  return { images, readouts, errors };
});
console.log(JSON.stringify(result));
