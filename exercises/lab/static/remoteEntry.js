/*
 * accelab-lab: a JupyterLab 4 extension written as a module-federation container by hand
 * (no build step, no dependency: it uses only what JupyterLab hands its plugins).
 *
 * nbgrader's Validate dialog says "Success! Your notebook passes all the tests." whenever
 * every test cell ran. In an accelab assignment the test cells check only that each answer
 * exists with the right form and dimension and that the notebook shows the values of the
 * student it will be collected as: the values are judged when the assignment is graded.
 * This plugin puts that sentence in place of nbgrader's when the notebook validated is an
 * accelab assignment (or when it cannot tell which notebook was validated: the Assignments
 * panel's Validate button).
 */
"use strict";
(function () {
  var NAME = "accelab-lab";
  var RUNTIME = "accelab.exercises.student.runtime";
  var MESSAGE =
    "Every answer has the right form and dimension, and this notebook shows the values of " +
    "the student it will be collected as. Validate does not judge the values: they are " +
    "judged when the assignment is graded, against the exact values of your own problem " +
    "(so a wrong number passes here).";

  function sourceOf(cell) {
    var s = cell && cell.source;
    return Array.isArray(s) ? s.join("") : String(s || "");
  }

  /* true: an accelab assignment; false: another notebook; null: cannot tell */
  function validatedIsAccelab(app) {
    var widget = app && app.shell && app.shell.currentWidget;
    var model = widget && widget.context && widget.context.model;
    if (!model || typeof model.toJSON !== "function") {
      return null;
    }
    var nb = model.toJSON();
    var cells = (nb && nb.cells) || [];
    return cells.some(function (c) {
      return sourceOf(c).indexOf(RUNTIME) !== -1;
    });
  }

  function rewrite(app, root) {
    var found = root.querySelectorAll
      ? root.querySelectorAll("#validation-message.validation-success")
      : [];
    found.forEach(function (message) {
      if (message.getAttribute("data-accelab") || validatedIsAccelab(app) === false) {
        return;
      }
      message.setAttribute("data-accelab", "1");
      var p = message.querySelector("p") || message.appendChild(document.createElement("p"));
      p.innerText = MESSAGE;
    });
  }

  var plugin = {
    id: NAME + ":validate-message",
    description: "Validate's message in an accelab assignment: values are judged at grading",
    autoStart: true,
    activate: function (app) {
      var observer = new MutationObserver(function (records) {
        records.forEach(function (record) {
          record.addedNodes.forEach(function (node) {
            if (node.nodeType === 1) {
              rewrite(app, node.parentNode || node);
            }
          });
        });
      });
      observer.observe(document.body, { childList: true, subtree: true });
    }
  };

  var modules = {
    "./extension": function () {
      return { __esModule: true, default: [plugin] };
    }
  };

  window._JUPYTERLAB = window._JUPYTERLAB || {};
  window._JUPYTERLAB[NAME] = {
    init: function () {
      return Promise.resolve();
    },
    get: function (module) {
      if (!modules[module]) {
        return Promise.reject(new Error(NAME + " has no module " + module));
      }
      return Promise.resolve(modules[module]);
    }
  };
})();
