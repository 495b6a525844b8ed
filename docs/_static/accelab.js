// accelab: mark display equations and tables that are wider than their box (they
// scroll), so the page shows a "swipe" cue under them; re-checked when the width
// changes.
(function () {
  function mark() {
    document.querySelectorAll("div.math").forEach(function (div) {
      var box = div.querySelector("mjx-container");
      if (!box) return;
      div.classList.toggle("scrolls", box.scrollWidth > box.clientWidth + 1);
    });
    document.querySelectorAll(".pst-scrollable-table-container").forEach(function (box) {
      box.classList.toggle("scrolls", box.scrollWidth > box.clientWidth + 1);
    });
  }
  function whenTypeset() {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      MathJax.startup.promise.then(mark);
    } else {
      mark();
    }
  }
  window.addEventListener("load", whenTypeset);
  window.addEventListener("resize", mark);
  document.addEventListener("toggle", mark, true);   // a folded answer opened
})();
