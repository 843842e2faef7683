// The page the live preview serves (preview_server.h): the image, a
// progress bar, the state and stats line, and the scene's errors. Its
// script polls /status four times a second and reloads the image when its
// version changes; it records in the body's data attributes what it shows
// (state, image version, images loaded), which the browser tests read.
#pragma once

namespace lancer::app {

inline constexpr const char* kPreviewPage = R"html(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>lancer preview</title>
<link rel="icon" href="data:,">
<style>
body { font: 14px system-ui, sans-serif; margin: 1.5em; background: #1e1e1e; color: #ddd; }
h1 { font-size: 1.1em; font-weight: normal; margin: 0 0 0.6em; }
#bar { width: 100%; max-width: 960px; height: 6px; background: #333; margin: 0.4em 0; }
#fill { height: 100%; width: 0; background: #4a9eff; transition: width 0.2s; }
#image { display: block; max-width: 100%; image-rendering: pixelated; background: #000; margin-top: 0.6em; }
#errors { color: #ff7b72; white-space: pre-wrap; font: 13px ui-monospace, monospace; margin: 0.6em 0; }
#errors:empty { display: none; }
#message { color: #aaa; font: 13px ui-monospace, monospace; }
.state { font-weight: bold; }
</style></head>
<body data-state="" data-image-version="0" data-images-loaded="0">
<h1>lancer: <span id="scene"></span> &mdash; <span id="state" class="state">connecting</span>
  <span id="percent"></span></h1>
<div id="bar"><div id="fill"></div></div>
<div id="message"></div>
<div id="errors" role="alert"></div>
<img id="image" alt="the render">
<script>
"use strict";
const body = document.body;
const image = document.getElementById("image");
let version = 0;
let loaded = 0;
image.addEventListener("load", () => {
  loaded += 1;
  body.dataset.imagesLoaded = String(loaded);
});
function show(status) {
  body.dataset.state = status.state;
  document.getElementById("scene").textContent = status.scene;
  document.getElementById("state").textContent = status.state;
  const percent = Math.round(100 * status.progress);
  document.getElementById("percent").textContent = status.state === "rendering" ? percent + "%" : "";
  document.getElementById("fill").style.width = (status.state === "done" ? 100 : percent) + "%";
  document.getElementById("message").textContent = status.message;
  document.getElementById("errors").textContent = status.errors.join("\n");
  if (status.image_version !== version && status.image_version > 0) {
    version = status.image_version;
    body.dataset.imageVersion = String(version);
    image.src = "/image.png?v=" + version;
  }
}
async function poll() {
  try {
    const response = await fetch("/status", { cache: "no-store" });
    if (response.ok) show(await response.json());
  } catch (error) {
    body.dataset.state = "disconnected";
    document.getElementById("state").textContent = "disconnected (lancer stopped?)";
  }
  setTimeout(poll, 250);
}
poll();
</script>
</body></html>
)html";

}  // namespace lancer::app
