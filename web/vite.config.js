// The front end is built once (npm run build) into a folder ncvm serve reads at run time:
// no network and no dev server is needed to use it.
import { defineConfig } from 'vite';

export default defineConfig({
  base: './',
  build: {
    outDir: process.env.NCVM_WEB_OUT || 'dist',
    emptyOutDir: true,
    chunkSizeWarningLimit: 1000,
    sourcemap: false,
  },
});
