// Markdown written by users (an experiment's description, its name, the names of its comparisons)
// rendered so that it runs no script: raw HTML is shown as text (except the empty placeholders fspm
// writes for the interactive parts), links lead only to http(s):, mailto: or a relative path, and
// images load only from http(s): or a relative path; any other link or image is shown as text.
// The HTML is built in an inert <template> (nothing loads, nothing runs) and checked there, after
// the browser has decoded entities and dropped tabs and line breaks from URLs, so an obfuscated
// "&#106;ava&#9;script:" is judged as the browser would follow it.
// Classic script: defines window.fspmSafeMarkdown(markdownText) -> DocumentFragment.
(function () {
  'use strict';
  const kRelative = 'fspm-relative:';
  const kLinkProtocols = new Set(['http:', 'https:', 'mailto:', kRelative]);
  const kImageProtocols = new Set(['http:', 'https:', kRelative]);
  const kPlaceholder = /^<div class="fspm-[a-z]+"><\/div>\s*$/;
  // Elements that load, run or submit something; none comes from Markdown without raw HTML.
  const kDropped = 'script, style, iframe, frame, object, embed, form, base, meta, link, svg, math';

  function escapeHtml(s) {
    return String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
  }

  // The URL's scheme as the browser would follow it ("javascript:"), kRelative for a relative
  // path, null when it is no URL at all.
  function protocolOf(url) {
    try {
      return new URL(url, kRelative + '/').protocol.toLowerCase();
    } catch (e) {
      return null;
    }
  }

  function allowed(url, protocols) {
    return url !== null && protocols.has(protocolOf(url));
  }

  // "text [url]": a link that is not followed, as the reader wrote it.
  function asText(doc, text, url) {
    return doc.createTextNode(url ? `${text} [${url}]` : text);
  }

  function clean(root) {
    const doc = root.ownerDocument;
    root.querySelectorAll(kDropped).forEach((e) => e.replaceWith(asText(doc, e.textContent, '')));
    for (const e of Array.from(root.querySelectorAll('*'))) {
      for (const a of Array.from(e.attributes)) {
        const name = a.name.toLowerCase();
        if (name.startsWith('on') || name === 'style' || name === 'srcdoc' || name === 'formaction' ||
            name === 'srcset' || name.includes(':')) e.removeAttribute(a.name);
      }
    }
    root.querySelectorAll('a').forEach((a) => {
      const href = a.getAttribute('href');
      if (href !== null && !allowed(href, kLinkProtocols)) a.replaceWith(asText(doc, a.textContent, href));
    });
    root.querySelectorAll('img').forEach((img) => {
      const src = img.getAttribute('src');
      if (!allowed(src, kImageProtocols)) img.replaceWith(asText(doc, img.getAttribute('alt') || '', src));
    });
  }

  let configured = false;
  window.fspmSafeMarkdown = function (markdown) {
    if (!configured) {
      marked.use({
        renderer: {
          html(token) {
            const t = token.text || token.raw || '';
            return kPlaceholder.test(t) ? t : escapeHtml(t);
          },
        },
      });
      configured = true;
    }
    const template = document.createElement('template');
    template.innerHTML = marked.parse(markdown);
    clean(template.content);
    return template.content;
  };
})();
