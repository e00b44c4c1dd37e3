// Impulse's bridge between the page and the app, as a miniquad plugin (the
// Rust side is src/web.rs): the state report tests and the page read, file
// downloads, local storage for autosave, the address's fragment for shared
// links, and the clicks of impacts through Web Audio. Loaded after macroquad's mq_js_bundle.js, whose
// UTF8ToString and wasm_memory it uses.
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
