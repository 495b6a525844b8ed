"""numpydoc's docstring template, compiled once per build instead of once per object.

numpydoc (1.x) builds a new Jinja environment and compiles its
``numpydoc_docstring.rst`` template for every object it documents: about a tenth of
a build of this site from scratch (2.6 of 24 cpu-s, 1,700 objects). The pages do not
change: the template is the same file, found the same way (through the builder's
template path, so a project's own override still wins), only compiled once.

numpydoc's ``setup(app, get_doc_object_=...)`` is its own hook for replacing
``get_doc_object``; this extension puts its version there after numpydoc has set up.
If numpydoc's internals ever differ from what it expects, it leaves numpydoc as it
is (the build is then slower, never different).
"""

import os


def _once(docscrape_sphinx):
    """A ``get_doc_object`` that compiles the template once per builder."""
    from jinja2 import FileSystemLoader
    from jinja2.sandbox import SandboxedEnvironment
    from sphinx.jinja2glue import BuiltinTemplateLoader

    folder = os.path.join(os.path.dirname(docscrape_sphinx.__file__), "templates")
    compiled = {}

    def template_for(builder):
        key = id(builder)
        if key not in compiled:
            if builder is not None:
                loader = BuiltinTemplateLoader()
                loader.init(builder, dirs=[folder])
            else:
                loader = FileSystemLoader([folder])
            env = SandboxedEnvironment(loader=loader)
            compiled[key] = (builder, env.get_template("numpydoc_docstring.rst"))
        return compiled[key][1]

    def get_doc_object(obj, what=None, doc=None, config=None, builder=None):
        config = {} if config is None else config
        config["template"] = template_for(builder)
        return docscrape_sphinx.get_doc_object_orig(
            obj,
            what=what,
            doc=doc,
            config=config,
            class_doc=docscrape_sphinx.SphinxClassDoc,
            func_doc=docscrape_sphinx.SphinxFunctionDoc,
            obj_doc=docscrape_sphinx.SphinxObjDoc,
        )

    return get_doc_object


def setup(app):
    app.setup_extension("numpydoc")
    try:
        from numpydoc import docscrape_sphinx
        from numpydoc import numpydoc as numpydoc_ext

        needed = ("get_doc_object_orig", "SphinxClassDoc", "SphinxFunctionDoc", "SphinxObjDoc")
        if all(hasattr(docscrape_sphinx, name) for name in needed) and hasattr(
            numpydoc_ext, "get_doc_object"
        ):
            numpydoc_ext.get_doc_object = _once(docscrape_sphinx)
    except ImportError:
        pass
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
