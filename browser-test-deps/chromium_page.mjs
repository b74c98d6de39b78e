// Opens a local HTML page in Debian's headless Chromium through playwright-core, with a
// fresh profile, collects the page's script errors and hands the page to `use`; shared
// by the page scripts of tests/browser/.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

// Resolves to what `use(page, errors)` returns; `errors` fills as scripts throw.
export async function withPage(executablePath, pagePath, use) {
  const profile = mkdtempSync(join(tmpdir(), 'skylit-chromium-'));  // a fresh --user-data-dir
  const context = await chromium.launchPersistentContext(profile, {
    executablePath,
    headless: true,
    viewport: { width: 1600, height: 1200 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
  try {
    const page = context.pages()[0] ?? await context.newPage();
    const errors = [];
    page.on('pageerror', error => errors.push(String(error)));
    page.on('console', message => { if (message.type() === 'error') errors.push(message.text()); });
    await page.goto(pathToFileURL(pagePath).href, { waitUntil: 'load' });
    return await use(page, errors);
  } finally {
    await context.close();
    rmSync(profile, { recursive: true, force: true });
  }
}
