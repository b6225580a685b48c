/*
 * Light or dark: the site marks its dark palette with body[data-md-color-scheme="slate"],
 * JupyterLab with body[data-jp-theme-light="false"]. The view follows changes.
 */

export function isDark(doc = document) {
  const body = doc.body;
  if (!body) return false;
  if (body.dataset.jpThemeLight !== undefined) return body.dataset.jpThemeLight === "false";
  return (body.dataset.mdColorScheme ?? doc.documentElement.dataset.mdColorScheme) === "slate";
}

/** Call onChange(dark) whenever the host switches between light and dark; returns a stop function. */
export function watchTheme(onChange, doc = document) {
  let dark = isDark(doc);
  const observer = new MutationObserver(() => {
    const now = isDark(doc);
    if (now !== dark) {
      dark = now;
      onChange(dark);
    }
  });
  const attributeFilter = ["data-md-color-scheme", "data-jp-theme-light", "data-jp-theme-name"];
  if (doc.body) observer.observe(doc.body, { attributes: true, attributeFilter });
  observer.observe(doc.documentElement, { attributes: true, attributeFilter });
  return () => observer.disconnect();
}

/**
 * The colour of one role from the host's palette ({role: {light, dark}}, trinormal.colors,
 * never copied here); the text's colour for a role the palette lacks.
 */
export function roleColor(palette, role, dark) {
  const entry = palette && palette[role];
  if (!entry) return surface(dark).text;
  return dark ? entry.dark : entry.light;
}

/** Background, text and grid colours of the view (not roles of the colour code). */
export function surface(dark) {
  return dark
    ? { background: "#1b1d24", text: "#f2f2f2", grid: "#4a4f5c", gridMajor: "#6b7180", line: "#ffd166" }
    : { background: "#ffffff", text: "#1a1a1a", grid: "#d4d7de", gridMajor: "#9aa0ab", line: "#b3261e" };
}
