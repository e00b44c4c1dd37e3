// Impulse's bridge between the page and the app, as a miniquad plugin (the
// Rust side is src/web.rs): the state report tests and the page read, file
// downloads, local storage for autosave, the address's fragment for shared
// links, the clicks of impacts through Web Audio, the page's language, and
// the accessible mirror beside the canvas (#mirror in index.html: real
// buttons and lists for the main commands, named in the window's language,
// and an aria-live region that says what happens). Loaded after macroquad's
// mq_js_bundle.js, whose UTF8ToString and wasm_memory it uses.
"use strict";
(function () {
    // Bytes set aside for the app, which fetches them with impulse_take.
    let pending = new Uint8Array(0);
    const text = (ptr, len) => UTF8ToString(ptr, len);
    const give = (string) => {
        pending = new TextEncoder().encode(string);
        return pending.length;
    };
    // Sound: browsers start an AudioContext only after a gesture, so it is
    // made (or resumed) on the first click, touch or key; clicks before
    // that are silent.
    let audio = null;
    const wakeAudio = () => {
        const Context = window.AudioContext || window.webkitAudioContext;
        if (!Context) return;
        if (audio === null) {
            try {
                audio = new Context();
            } catch (e) {
                return; // no sound here
            }
        }
        if (audio.state === "suspended") audio.resume();
    };
    window.addEventListener("pointerdown", wakeAudio, true);
    window.addEventListener("keydown", wakeAudio, true);
    // One click, as app::audio::synth makes it on the desktop: a sine of
    // `hz` rising over `attack` s (half a cosine there, a line here) to
    // `amplitude`, decaying with time constant `decay`, faded to silence
    // by `seconds`; `delay` s from now.
    const FADE = 0.002;
    const playClick = (hz, amplitude, attack, decay, seconds, delay) => {
        window.impulseClicks = (window.impulseClicks || 0) + 1;
        if (audio === null || audio.state !== "running" || !(amplitude > 0)) return;
        const t = audio.currentTime + 0.005 + Math.max(0, delay);
        const tone = audio.createOscillator();
        const gain = audio.createGain();
        tone.type = "sine";
        tone.frequency.value = hz;
        gain.gain.setValueAtTime(0, t);
        gain.gain.linearRampToValueAtTime(amplitude, t + attack);
        gain.gain.setTargetAtTime(0, t + attack, decay);
        const fadeFrom = t + seconds - FADE;
        gain.gain.setValueAtTime(amplitude * Math.exp(-(seconds - FADE - attack) / decay), fadeFrom);
        gain.gain.linearRampToValueAtTime(0, t + seconds);
        tone.connect(gain);
        gain.connect(audio.destination);
        tone.start(t);
        tone.stop(t + seconds);
        tone.onended = () => gain.disconnect();
    };

    // The accessible mirror. The app describes it (src/app/model/mirror.rs)
    // whenever a name or a state changes; a control used is handed back
    // with impulse_mirror_use(list, index): list 0 buttons, 1 presets,
    // 2 languages.
    const use = (list, index) => {
        if (typeof wasm_exports !== "undefined" && wasm_exports.impulse_mirror_use) {
            wasm_exports.impulse_mirror_use(list, index);
        }
    };
    let mirrorShape = "";
    const choice = (id, list, spec) => {
        const select = document.getElementById(id);
        const label = document.querySelector(`label[for="${id}"]`);
        label.textContent = spec.label;
        select.replaceChildren();
        if (list === 1) {
            // Presets: a choice opens one; the first line only names the list.
            const none = new Option("…", "");
            select.add(none);
        }
        spec.options.forEach((name, i) => select.add(new Option(name, String(i))));
        if (spec.chosen !== null && spec.chosen !== undefined) select.value = String(spec.chosen);
        select.onchange = () => {
            if (select.value !== "") use(list, Number(select.value));
            if (list === 1) select.value = "";
        };
    };
    const buildMirror = (spec) => {
        const shape = JSON.stringify([spec.lang, spec.buttons.map((b) => b.label), spec.presets, spec.languages]);
        const region = document.getElementById("mirror");
        if (shape !== mirrorShape) {
            mirrorShape = shape;
            region.setAttribute("aria-label", spec.title);
            document.getElementById("glcanvas").setAttribute("aria-label", spec.canvas);
            document.getElementById("mirror-title").textContent = spec.title;
            const row = document.getElementById("mirror-buttons");
            const focused = document.activeElement && row.contains(document.activeElement)
                ? [...row.children].indexOf(document.activeElement) : -1;
            row.replaceChildren();
            spec.buttons.forEach((b, i) => {
                const button = document.createElement("button");
                button.type = "button";
                button.textContent = b.label;
                button.addEventListener("click", () => use(0, i));
                row.appendChild(button);
            });
            if (focused >= 0 && row.children[focused]) row.children[focused].focus();
            choice("mirror-presets", 1, spec.presets);
            choice("mirror-languages", 2, spec.languages);
            document.getElementById("mirror-said-label").textContent = spec.said;
        }
        // States and hints change without rebuilding (focus stays put).
        const row = document.getElementById("mirror-buttons");
        spec.buttons.forEach((b, i) => {
            const button = row.children[i];
            button.title = b.hint;
            if (b.shortcut) button.setAttribute("aria-keyshortcuts", b.shortcut);
            if (b.pressed === null || b.pressed === undefined) button.removeAttribute("aria-pressed");
            else button.setAttribute("aria-pressed", String(b.pressed));
        });
    };
    // What happens, said: at most one update a second (lines that come
    // together are said together), so a screen reader is not flooded.
    let toSay = [];
    let sayTimer = null;
    const say = (line) => {
        toSay.push(line);
        (window.impulseSaid = window.impulseSaid || []).push(line);
        if (sayTimer !== null) return;
        const flush = () => {
            const live = document.getElementById("mirror-said");
            if (toSay.length === 0) {
                sayTimer = null;
                return;
            }
            live.textContent = toSay.join(" ");
            toSay = [];
            sayTimer = setTimeout(flush, 1000);
        };
        flush();
    };
    // No keyboard trap: macroquad's canvas keeps Tab for itself (the
    // panels' controls); while the world has the keys, Shift+Tab leaves the
    // canvas for the mirror's last control.
    let worldKeys = true;
    window.addEventListener("keydown", (e) => {
        const canvas = document.getElementById("glcanvas");
        if (e.key !== "Tab" || !e.shiftKey || document.activeElement !== canvas || !worldKeys) return;
        const controls = document.querySelectorAll("#mirror button, #mirror select");
        if (controls.length === 0) return;
        e.preventDefault();
        e.stopImmediatePropagation();
        controls[controls.length - 1].focus();
    }, true);
    // The sandbox's own Ctrl keys (save, undo, redo, the dock's tabs) are
    // the page's while the canvas has the keys: without this the browser
    // would also save the page, or switch to its own third tab on Ctrl+3.
    // macroquad still gets the key (the event goes on to the canvas).
    // (A test holds this list to the bindings table's Ctrl chords.)
    const OWN_CTRL = new Set(["KeyS", "KeyZ", "KeyY", "Digit1", "Digit2", "Digit3", "Digit4", "Digit5", "Digit6"]);
    // And Ctrl+A, which selects a field's text in the canvas: the browser
    // also selected the whole page's (the mirror's words in blue).
    const FIELD_CTRL = new Set(["KeyA"]);
    window.addEventListener("keydown", (e) => {
        const canvas = document.getElementById("glcanvas");
        if (!e.ctrlKey || e.altKey || e.metaKey || document.activeElement !== canvas) return;
        if (OWN_CTRL.has(e.code) || FIELD_CTRL.has(e.code)) e.preventDefault();
    }, true);
    function register(importObject) {
        const env = importObject.env;
        env.impulse_report_state = (ptr, len) => {
            window.impulseState = text(ptr, len);
            if (window.impulseFirstReport === undefined) {
                window.impulseFirstReport = performance.now();
                const loading = document.getElementById("loading");
                if (loading) loading.remove();
            }
        };
        env.impulse_download = (namePtr, nameLen, dataPtr, dataLen) => {
            const name = text(namePtr, nameLen);
            const data = new Uint8Array(wasm_memory.buffer, dataPtr, dataLen).slice();
            const url = URL.createObjectURL(new Blob([data]));
            const link = document.createElement("a");
            link.href = url;
            link.download = name;
            document.body.appendChild(link);
            link.click();
            link.remove();
            setTimeout(() => URL.revokeObjectURL(url), 60000);
            (window.impulseDownloads = window.impulseDownloads || []).push({ name, bytes: dataLen });
        };
        env.impulse_storage_set = (keyPtr, keyLen, valuePtr, valueLen) => {
            try {
                localStorage.setItem(text(keyPtr, keyLen), text(valuePtr, valueLen));
                return 1;
            } catch (e) {
                return 0; // quota exceeded, or storage turned off
            }
        };
        env.impulse_storage_get = (keyPtr, keyLen) => {
            let value = null;
            try {
                value = localStorage.getItem(text(keyPtr, keyLen));
            } catch (e) {
                value = null;
            }
            return value === null ? -1 : give(value);
        };
        env.impulse_storage_remove = (keyPtr, keyLen) => {
            try {
                localStorage.removeItem(text(keyPtr, keyLen));
            } catch (e) {
                // nothing kept, nothing to remove
            }
        };
        env.impulse_fragment_get = () => give(window.location.hash.replace(/^#/, ""));
        env.impulse_fragment_set = (ptr, len) => {
            history.replaceState(null, "", "#" + text(ptr, len));
        };
        env.impulse_report_fingerprints = (ptr, len) => {
            window.impulseFingerprints = text(ptr, len);
        };
        env.impulse_now = () => performance.now() / 1000;
        env.impulse_click = playClick;
        env.impulse_browser_language = () => give(navigator.language || "en");
        env.impulse_set_page_language = (tagPtr, tagLen, titlePtr, titleLen) => {
            document.documentElement.lang = text(tagPtr, tagLen);
            document.title = text(titlePtr, titleLen);
        };
        env.impulse_mirror = (ptr, len) => buildMirror(JSON.parse(text(ptr, len)));
        env.impulse_say = (ptr, len) => say(text(ptr, len));
        env.impulse_world_keys = (on) => {
            worldKeys = on !== 0;
        };
        env.impulse_take = (ptr, len) => {
            new Uint8Array(wasm_memory.buffer, ptr, len).set(pending.subarray(0, len));
            pending = new Uint8Array(0);
        };
    }
    miniquad_add_plugin({ register_plugin: register, name: "impulse", version: 1 });
    // Hidden or left: the app keeps its sandbox now (a reload or a return
    // reopens it), not at the next autosave.
    const keepNow = () => {
        if (typeof wasm_exports !== "undefined" && wasm_exports.impulse_keep_now) {
            wasm_exports.impulse_keep_now();
        }
    };
    document.addEventListener("visibilitychange", () => {
        if (document.visibilityState === "hidden") keepNow();
    });
    window.addEventListener("pagehide", keepNow);
})();
