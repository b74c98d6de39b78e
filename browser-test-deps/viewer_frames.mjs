// Opens the viewer.html of `skylit animate` in headless Chromium and prints, as one JSON
// line, what a person sees at each frame: the frame reached by moving the slider to each
// position in turn, by the arrow key from the first, and by the play button; for each,
// the slider's value, the label, the image's load state and size, and its pixels (RGB,
// row by row, read back through a canvas). tests/app/animate_viewer_browser_test.cpp
// checks them against the frames animate wrote.
//
//   node viewer_frames.mjs CHROMIUM VIEWER.html
import { withPage } from './chromium_page.mjs';

const [executablePath, pagePath] = process.argv.slice(2);

// The frame on show once its image has decoded.
async function shown(page) {
  await page.waitForFunction(() => {
    const img = document.getElementById('frame');
    return img.complete && img.naturalWidth > 0;
  });
  return page.evaluate(() => {
    const img = document.getElementById('frame');
    const canvas = document.createElement('canvas');
    canvas.width = img.naturalWidth;
    canvas.height = img.naturalHeight;
    const context = canvas.getContext('2d');
    context.drawImage(img, 0, 0);
    const rgba = context.getImageData(0, 0, canvas.width, canvas.height).data;
    const rgb = [];
    for (let i = 0; i < rgba.length; i += 4) rgb.push(rgba[i], rgba[i + 1], rgba[i + 2]);
    return { slider: Number(document.getElementById('slider').value), label: document.getElementById('label').textContent,
             complete: img.complete, width: img.naturalWidth, height: img.naturalHeight, rgb };
  });
}

const result = await withPage(executablePath, pagePath, async (page, errors) => {
  const slider = page.locator('#slider');
  const count = Number(await slider.getAttribute('max')) + 1;
  const first = await shown(page);
  const bySlider = [];
  for (let i = count - 1; i >= 0; --i) {  // backwards, so that each move changes the frame
    await slider.fill(String(i));  // sets the value and fires "input", as a drag does
    bySlider[i] = await shown(page);
  }
  await slider.focus();
  await page.keyboard.press('ArrowRight');
  const byKey = await shown(page);
  // Play from the second frame: the slider moves on by itself; pause, and the frame on
  // show is the one the slider says.
  await page.click('#play');
  await page.waitForFunction(() => Number(document.getElementById('slider').value) !== 1);
  await page.click('#play');
  const afterPlay = await shown(page);
  const playText = await page.textContent('#play');
  return { count, first, bySlider, byKey, afterPlay, playText, errors };
});
console.log(JSON.stringify(result));
