// Typeset the site's TeX once, when it is built (docs/_ext/math_at_build.py runs this).
//
// usage: node math_at_build.js MATHJAX_DIR FONT_URL < formulas.json > typeset.json
//
// formulas.json: [[tex, display], ...]. typeset.json: {"html": [one <mjx-container> per
// formula, in order], "css": the CHTML stylesheet those formulas need (their characters only),
// "errors": [[index, message], ...] for a formula MathJax could not read}.
//
// MathJax is the copy the site serves (sphinx-mathjax-offline's es5 build, whose node-main.js
// typesets with MathJax's own DOM and no browser); the same TeX input and CHTML output as the
// page script, with the same configuration as docs/conf.py's mathjax3_config.
"use strict";

const [mathjaxDir, fontURL] = process.argv.slice(2);
const formulas = JSON.parse(require("fs").readFileSync(0, "utf8"));

// the browser measures these from the page; a phone's and a laptop's differ only in em [px]
const EM = 16;
const EX = 8;
const CONTAINER_WIDTH = 80 * EM;

require(`${mathjaxDir}/node-main.js`)
  .init({
    loader: { load: ["input/tex", "output/chtml"] },
    tex: { tags: "none" },
    chtml: { fontURL },
  })
  .then((MathJax) => {
    const adaptor = MathJax.startup.adaptor;
    const errors = [];
    const html = formulas.map(([tex, display], index) => {
      const node = MathJax.tex2chtml(tex, {
        display,
        em: EM,
        ex: EX,
        containerWidth: CONTAINER_WIDTH,
      });
      const error = adaptor.tags(node, "mjx-merror")[0];
      if (error) errors.push([index, adaptor.getAttribute(error, "data-mjx-error") || "TeX error"]);
      return adaptor.outerHTML(node);
    });
    const css = adaptor.textContent(MathJax.chtmlStylesheet());
    process.stdout.write(JSON.stringify({ html, css, errors }));
  })
  .catch((err) => {
    process.stderr.write(`MathJax could not start: ${err.message}\n`);
    process.exit(1);
  });
