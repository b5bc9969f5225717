// The page's colour theme, dark or light: the header's button switches it, localStorage keeps
// it. The 3D view's background follows the theme's --view-bg; a 'themechange' event tells
// whoever draws in theme colours (the path highlight) to read them again.
const KEY = 'ncvm.theme';

export function initTheme(view, button) {
  const apply = (theme) => {
    document.documentElement.dataset.theme = theme;
    const bg = getComputedStyle(document.documentElement).getPropertyValue('--view-bg').trim();
    view.renderer.setClearColor(bg || '#15181d');
    themeGrid(view);
    button.textContent = theme === 'light' ? 'Dark' : 'Light';
    button.title = `Switch to the ${theme === 'light' ? 'dark' : 'light'} theme`;
    window.dispatchEvent(new Event('themechange'));
  };
  apply(localStorage.getItem(KEY) === 'light' ? 'light' : 'dark');
  button.addEventListener('click', () => {
    const next = document.documentElement.dataset.theme === 'light' ? 'dark' : 'light';
    localStorage.setItem(KEY, next);
    apply(next);
  });
}

// The view's grid in the theme's grid colour (three's GridHelper is made with dark-theme
// colours): after each new model and each switch of theme.
export function themeGrid(view) {
  const colour = getComputedStyle(document.documentElement).getPropertyValue('--view-grid').trim();
  view.scene.traverse((o) => {
    if (o.type !== 'GridHelper') return;
    if (colour) {
      o.material.vertexColors = false;
      o.material.color.set(colour);
    } else o.material.vertexColors = true;
    o.material.needsUpdate = true;
  });
  view.draw();
}
