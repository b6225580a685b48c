/* trinormal 3D views (the explorer and the mesh view). Bundles three.js 0.187.0, three-mesh-bvh 0.9.17 and meshoptimizer 1.3.0 (MIT licences, see THIRD_PARTY_LICENSES.txt). Built by js/explorer/build.mjs. */
const G=globalThis.__trinormalExplorer||(globalThis.__trinormalExplorer={});
const R=G["e58ba0b3ffafe222"]||(G["e58ba0b3ffafe222"]=(()=>{var tnxModule=(()=>{var rh=Object.defineProperty;var Vb=Object.getOwnPropertyDescriptor;var Hb=Object.getOwnPropertyNames;var Gb=Object.prototype.hasOwnProperty;var ua=(i,t,e)=>()=>{if(e)throw e[0];try{return i&&(t=i(i=0)),t}catch(n){throw e=[n],n}};var $u=(i,t)=>{for(var e in t)rh(i,e,{get:t[e],enumerable:!0})},Wb=(i,t,e,n)=>{if(t&&typeof t=="object"||typeof t=="function")for(let a of Hb(t))!Gb.call(i,a)&&a!==e&&rh(i,a,{get:()=>t[a],enumerable:!(n=Vb(t,a))||n.enumerable});return i};var La=i=>Wb(rh({},"__esModule",{value:!0}),i);function hx(i){for(let t=i.length-1;t>=0;--t)if(i[t]>=65535)return!0;return!1}function dx(i){return ArrayBuffer.isView(i)&&!(i instanceof DataView)}function ir(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function Lp(){let i=ir("canvas");return i.style.display="block",i}function ar(...i){let t="THREE."+i.shift();$a?$a("log",t,...i):console.log(t,...i)}function Dp(i){let t=i[0];if(typeof t=="string"&&t.startsWith("TSL:")){let e=i[1];e&&e.isStackTrace?i[0]+=" "+e.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function Rt(...i){i=Dp(i);let t="THREE."+i.shift();if($a)$a("warn",t,...i);else{let e=i[0];e&&e.isStackTrace?console.warn(e.getError(t)):console.warn(t,...i)}}function Lt(...i){i=Dp(i);let t="THREE."+i.shift();if($a)$a("error",t,...i);else{let e=i[0];e&&e.isStackTrace?console.error(e.getError(t)):console.error(t,...i)}}function Zs(...i){let t=i.join(" ");t in xf||(xf[t]=!0,Rt(...i))}function Up(i,t,e){return new Promise(function(n,a){function s(){switch(i.clientWaitSync(t,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:a();break;case i.TIMEOUT_EXPIRED:setTimeout(s,e);break;default:n()}}setTimeout(s,e)})}function ta(){let i=Math.random()*4294967295|0,t=Math.random()*4294967295|0,e=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(Ze[i&255]+Ze[i>>8&255]+Ze[i>>16&255]+Ze[i>>24&255]+"-"+Ze[t&255]+Ze[t>>8&255]+"-"+Ze[t>>16&15|64]+Ze[t>>24&255]+"-"+Ze[e&63|128]+Ze[e>>8&255]+"-"+Ze[e>>16&255]+Ze[e>>24&255]+Ze[n&255]+Ze[n>>8&255]+Ze[n>>16&255]+Ze[n>>24&255]).toLowerCase()}function Bt(i,t,e){return Math.max(t,Math.min(e,i))}function bd(i,t){return(i%t+t)%t}function ux(i,t,e,n,a){return n+(i-t)*(a-n)/(e-t)}function fx(i,t,e){return i!==t?(e-i)/(t-i):0}function Qs(i,t,e){return(1-e)*i+e*t}function px(i,t,e,n){return Qs(i,t,1-Math.exp(-e*n))}function mx(i,t=1){return t-Math.abs(bd(i,t*2)-t)}function gx(i,t,e){return i<=t?0:i>=e?1:(i=(i-t)/(e-t),i*i*(3-2*i))}function bx(i,t,e){return i<=t?0:i>=e?1:(i=(i-t)/(e-t),i*i*i*(i*(i*6-15)+10))}function xx(i,t){return i+Math.floor(Math.random()*(t-i+1))}function yx(i,t){return i+Math.random()*(t-i)}function _x(i){return i*(.5-Math.random())}function vx(i){i!==void 0&&(yf=i);let t=yf+=1831565813;return t=Math.imul(t^t>>>15,t|1),t^=t+Math.imul(t^t>>>7,t|61),((t^t>>>14)>>>0)/4294967296}function Mx(i){return i*$s}function Sx(i){return i*Qa}function wx(i){return i>0&&Number.isInteger(i)&&2**Math.round(Math.log2(i))===i}function Ax(i){return Math.pow(2,Math.ceil(Math.log(i)/Math.LN2))}function xd(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function Ex(i,t,e,n,a){let s=Math.cos,r=Math.sin,o=s(e/2),c=r(e/2),l=s((t+n)/2),h=r((t+n)/2),u=s((t-n)/2),d=r((t-n)/2),f=s((n-t)/2),m=r((n-t)/2);switch(a){case"XYX":i.set(o*h,c*u,c*d,o*l);break;case"YZY":i.set(c*d,o*h,c*u,o*l);break;case"ZXZ":i.set(c*u,c*d,o*h,o*l);break;case"XZX":i.set(o*h,c*m,c*f,o*l);break;case"YXY":i.set(c*f,o*h,c*m,o*l);break;case"ZYZ":i.set(c*m,c*f,o*h,o*l);break;default:Rt("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+a)}}function dl(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function yd(i,t){if(t.constructor===Float32Array)return i;let e=dl(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/e,-1)}function _d(i,t){if(t.constructor===Float32Array)return i;let e=dl(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*e)}function Tx(){let i={enabled:!0,workingColorSpace:er,spaces:{},convert:function(a,s,r){return this.enabled===!1||s===r||!s||!r||(this.spaces[s].transfer===ie&&(a.r=Ei(a.r),a.g=Ei(a.g),a.b=Ei(a.b)),this.spaces[s].primaries!==this.spaces[r].primaries&&(a.applyMatrix3(this.spaces[s].toXYZ),a.applyMatrix3(this.spaces[r].fromXYZ)),this.spaces[r].transfer===ie&&(a.r=Ja(a.r),a.g=Ja(a.g),a.b=Ja(a.b))),a},workingToColorSpace:function(a,s){return this.convert(a,this.workingColorSpace,s)},colorSpaceToWorking:function(a,s){return this.convert(a,s,this.workingColorSpace)},getPrimaries:function(a){return this.spaces[a].primaries},getTransfer:function(a){return a===Di?nr:this.spaces[a].transfer},getToneMappingMode:function(a){return this.spaces[a].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(a,s=this.workingColorSpace){return a.fromArray(this.spaces[s].luminanceCoefficients)},define:function(a){Object.assign(this.spaces,a)},_getMatrix:function(a,s,r){return a.copy(this.spaces[r].fromXYZ).multiply(this.spaces[s].toXYZ)},_getDrawingBufferColorSpace:function(a){return this.spaces[a].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(a=this.workingColorSpace){return this.spaces[a].workingColorSpaceConfig.unpackColorSpace}},t=[.64,.33,.3,.6,.15,.06],e=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[er]:{primaries:t,whitePoint:n,transfer:nr,toXYZ:vf,fromXYZ:Mf,luminanceCoefficients:e,workingColorSpaceConfig:{unpackColorSpace:En},outputColorSpaceConfig:{drawingBufferColorSpace:En}},[En]:{primaries:t,whitePoint:n,transfer:ie,toXYZ:vf,fromXYZ:Mf,luminanceCoefficients:e,outputColorSpaceConfig:{drawingBufferColorSpace:En}}}),i}function Ei(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function Ja(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}function mh(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?ac.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(Rt("Texture: Unable to serialize Texture."),{})}function xh(i,t,e){return e<0&&(e+=1),e>1&&(e-=1),e<1/6?i+(t-i)*6*e:e<1/2?t:e<2/3?i+(t-i)*6*(2/3-e):i}function Eh(i,t,e,n,a){for(let s=0,r=i.length-3;s<=r;s+=3){pa.fromArray(i,s);let o=a.x*Math.abs(pa.x)+a.y*Math.abs(pa.y)+a.z*Math.abs(pa.z),c=t.dot(pa),l=e.dot(pa),h=n.dot(pa);if(Math.max(-Math.max(c,l,h),Math.min(c,l,h))>o)return!1}return!0}function Nf(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=ta()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}function Gx(i,t,e,n,a,s,r,o){let c;if(t.side===Ge?c=n.intersectTriangle(r,s,a,!0,o):c=n.intersectTriangle(a,s,r,t.side===ci,o),c===null)return null;Lo.copy(o),Lo.applyMatrix4(i.matrixWorld);let l=e.ray.origin.distanceTo(Lo);return l<e.near||l>e.far?null:{distance:l,point:Lo.clone(),object:i}}function Do(i,t,e,n,a,s,r,o,c,l){i.getVertexPosition(o,Ro),i.getVertexPosition(c,Co),i.getVertexPosition(l,No);let h=Gx(i,t,e,n,Ro,Co,No,Df);if(h){let u=new F;ai.getBarycoord(Df,Ro,Co,No,u),a&&(h.uv=ai.getInterpolatedAttribute(a,o,c,l,u,new Ct)),s&&(h.uv1=ai.getInterpolatedAttribute(s,o,c,l,u,new Ct)),r&&(h.normal=ai.getInterpolatedAttribute(r,o,c,l,u,new F),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));let d={a:o,b:c,c:l,normal:new F,materialIndex:0};ai.getNormal(Ro,Co,No,d.normal),h.face=d,h.barycoord=u}return h}function Ph(i,t){return i-t}function jx(i,t){return i.z-t.z}function Xx(i,t){return t.z-i.z}function Zx(i,t,e=0){let n=t.itemSize;if(i.isInterleavedBufferAttribute||i.array.constructor!==t.array.constructor){let a=i.count;for(let s=0;s<a;s++)for(let r=0;r<n;r++)t.setComponent(s+e,r,i.getComponent(s,r))}else t.array.set(i.array,e*n);t.needsUpdate=!0}function ni(i,t){if(i.constructor!==t.constructor){let e=Math.min(i.length,t.length);for(let n=0;n<e;n++)t[n]=i[n]}else{let e=Math.min(i.length,t.length);t.set(new i.constructor(i.buffer,0,e))}}function ko(i,t,e,n,a,s,r){let o=i.geometry.attributes.position;if(cc.fromBufferAttribute(o,a),lc.fromBufferAttribute(o,s),e.distanceSqToSegment(cc,lc,Uh,kf)>n)return;Uh.applyMatrix4(i.matrixWorld);let l=t.ray.origin.distanceTo(Uh);if(!(l<t.near||l>t.far))return{distance:l,point:kf.clone().applyMatrix4(i.matrixWorld),index:r,face:null,faceIndex:null,barycoord:null,object:i}}function Gf(i,t,e,n,a,s,r){let o=Gh.distanceSqToPoint(i);if(o<e){let c=new F;Gh.closestPointToPoint(i,c),c.applyMatrix4(n);let l=a.ray.origin.distanceTo(c);if(l<a.near||l>a.far)return;s.push({distance:l,distanceToRay:Math.sqrt(o),point:c,index:t,face:null,faceIndex:null,barycoord:null,object:r})}}function Wf(i,t,e){let n=`${i.x},${i.y},${i.z}-${t.x},${t.y},${t.z}`,a=`${t.x},${t.y},${t.z}-${i.x},${i.y},${i.z}`;return e.has(n)===!0||e.has(a)===!0?!1:(e.add(n),e.add(a),!0)}function Ta(i){let t={};for(let e in i){t[e]={};for(let n in i[e]){let a=i[e][n];if(jf(a))a.isRenderTargetTexture?(Rt("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),t[e][n]=null):t[e][n]=a.clone();else if(Array.isArray(a))if(jf(a[0])){let s=[];for(let r=0,o=a.length;r<o;r++)s[r]=a[r].clone();t[e][n]=s}else t[e][n]=a.slice();else t[e][n]=a}}return t}function nn(i){let t={};for(let e=0;e<i.length;e++){let n=Ta(i[e]);for(let a in n)t[a]=n[a]}return t}function jf(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function $x(i){let t=[];for(let e=0;e<i.length;e++)t.push(i[e].clone());return t}function vd(i){let t=i.getRenderTarget();return t===null?i.outputColorSpace:t.isXRRenderTarget===!0?t.texture.colorSpace:Gt.workingColorSpace}function Wa(i,t){return!i||i.constructor===t?i:typeof t.BYTES_PER_ELEMENT=="number"?new t(i):Array.prototype.slice.call(i)}function Ho(i){return i!==void 0&&i.inTangents!==void 0&&i.outTangents!==void 0}function Bp(i,t,e,n,a){let s=1-i;return s*s*s*t+3*s*s*i*e+3*s*i*i*n+i*i*i*a}function e0(i,t,e,n,a){let s=1-i;return 3*s*s*(e-t)+6*s*i*(n-e)+3*i*i*(a-n)}function n0(i,t,e,n,a){let s=(i-t)/(a-t);for(let r=0;r<8;r++){let o=Bp(s,t,e,n,a)-i;if(Math.abs(o)<1e-10)break;let c=e0(s,t,e,n,a);if(Math.abs(c)<1e-10)break;s=Math.max(0,Math.min(1,s-o/c))}return s}function Xf(i,t){for(let e=0,n=i.length;e!==n;e+=2)i[e]+=t}function qf(i,t){for(let e=0,n=i.length;e!==n;e+=2)i[e]*=t}function Qf(i,t){return i.distance-t.distance}function Xh(i,t,e,n){let a=!0;if(i.layers.test(t.layers)&&i.raycast(t,e)===!1&&(a=!1),a===!0&&n===!0){let s=i.children;for(let r=0,o=s.length;r<o;r++)Xh(s[r],t,e,!0)}}function wd(i,t,e,n){let a=f0(n);switch(e){case hd:return i*t;case Or:return i*t/a.components*a.byteLength;case Aa:return i*t/a.components*a.byteLength;case hi:return i*t*2/a.components*a.byteLength;case fs:return i*t*2/a.components*a.byteLength;case dd:return i*t*3/a.components*a.byteLength;case mn:return i*t*4/a.components*a.byteLength;case ps:return i*t*4/a.components*a.byteLength;case Fr:case Br:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case kr:case zr:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Uc:case Fc:return Math.max(i,16)*Math.max(t,8)/4;case Dc:case Oc:return Math.max(i,8)*Math.max(t,8)/2;case Bc:case kc:case Vc:case Hc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case zc:case Vr:case Gc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Wc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case jc:return Math.floor((i+4)/5)*Math.floor((t+3)/4)*16;case Xc:return Math.floor((i+4)/5)*Math.floor((t+4)/5)*16;case qc:return Math.floor((i+5)/6)*Math.floor((t+4)/5)*16;case Yc:return Math.floor((i+5)/6)*Math.floor((t+5)/6)*16;case Jc:return Math.floor((i+7)/8)*Math.floor((t+4)/5)*16;case Kc:return Math.floor((i+7)/8)*Math.floor((t+5)/6)*16;case Zc:return Math.floor((i+7)/8)*Math.floor((t+7)/8)*16;case $c:return Math.floor((i+9)/10)*Math.floor((t+4)/5)*16;case Qc:return Math.floor((i+9)/10)*Math.floor((t+5)/6)*16;case tl:return Math.floor((i+9)/10)*Math.floor((t+7)/8)*16;case el:return Math.floor((i+9)/10)*Math.floor((t+9)/10)*16;case nl:return Math.floor((i+11)/12)*Math.floor((t+9)/10)*16;case il:return Math.floor((i+11)/12)*Math.floor((t+11)/12)*16;case al:case sl:case rl:return Math.ceil(i/4)*Math.ceil(t/4)*16;case ol:case cl:return Math.ceil(i/4)*Math.ceil(t/4)*8;case Hr:case ll:return Math.ceil(i/4)*Math.ceil(t/4)*16}throw new Error(`Unable to determine texture byte length for ${e} format.`)}function f0(i){switch(i){case en:case Dr:return{byteLength:1,components:1};case Qi:case Ur:case Zn:return{byteLength:2,components:1};case Pc:case Lc:return{byteLength:2,components:4};case Mn:case us:case pn:return{byteLength:4,components:1};case cd:case ld:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}var Tc,$i,oi,ep,Yh,np,Pr,ip,ls,ci,Ge,kn,va,hs,Jh,Kh,Zh,ap,Ma,sp,rp,op,cp,lp,hp,dp,up,$h,Qh,fp,pp,mp,gp,bp,xp,yp,_p,vp,Yo,Jo,Ko,Ka,Zo,$o,Qo,tc,Ic,Mp,Sp,li,td,ed,nd,id,ad,sd,rd,od,Sa,ds,Rc,Cc,ec,si,nc,we,wp,Lr,fn,Nc,Pi,en,Dr,Ur,Qi,us,Mn,pn,Zn,Pc,Lc,wa,cd,ld,hd,dd,mn,Ii,Li,Or,Aa,hi,fs,ps,Fr,Br,kr,zr,Dc,Uc,Oc,Fc,Bc,kc,zc,Vc,Hc,Vr,Gc,Wc,jc,Xc,qc,Yc,Jc,Kc,Zc,$c,Qc,tl,el,nl,il,al,sl,rl,ol,cl,Hr,ll,tr,ic,Xo,Bh,kh,zh,Vh,Ap,hl,Ep,Di,En,er,nr,ie,qo,Tp,Ip,Rp,Cp,ud,Np,Pp,fd,pd,md,gd,Fn,Za,xf,$a,Op,Yn,Ze,yf,$s,Qa,Ea,Ad,Ct,Tn,Ed,F,fh,_f,Td,Dt,ph,vf,Mf,Gt,Da,ac,Ix,ts,Rx,gh,vn,Id,$t,sc,In,sr,rc,Ec,Zt,Ua,jn,Cx,Nx,Gi,yo,wn,Sf,wf,Ri,es,Px,Af,Oa,_i,_o,Xs,Lx,Dx,Ef,Tf,If,Rf,Ux,Fa,bh,Re,Ai,Ox,ns,Fp,Wi,vo,kt,$e,rr,Xn,vi,yh,Mi,Ba,ka,Cf,_h,vh,Mh,Sh,wh,Ah,ai,Ie,Si,qn,Mo,za,Va,Ha,ji,Xi,fa,qs,So,wo,pa,Se,Ao,Fx,un,or,cr,re,Bx,Ys,Th,ze,kx,On,Ih,Ga,An,Js,ke,Ae,oc,ln,Jn,Rh,zx,Vx,hn,Hx,ri,wi,Ch,Eo,To,Kn,is,Pf,ma,Io,Lf,Ro,Co,No,Nh,Po,Df,Lo,tn,Ti,ga,Wx,Uo,Ci,Uf,lr,Hh,_n,qx,Yx,Jx,Oo,ba,Lh,Of,Ff,Kx,Dh,Qe,Fo,hr,xa,cc,lc,Bf,Ks,Bo,Uh,kf,ya,zf,Vf,as,dr,hc,Hf,Gh,zo,Vo,ur,fr,Ni,pr,mr,ss,rs,gr,br,xr,yr,_r,Gr,Qx,t0,Bn,dc,vr,uc,fc,Yi,pc,mc,gc,bc,Rn,Ji,xc,yc,_c,Mr,Ki,vc,Mc,kp,Sc,Sr,Oh,Yf,Jf,wc,Go,Wo,ii,wr,qi,Kf,Zf,dn,Ar,Wh,Er,Tr,Ir,ja,Xa,os,Ac,Md,i0,Sd,a0,s0,r0,o0,c0,l0,h0,jh,fe,BA,Zi,$f,Rr,cs,Rd,qh,tp,jo,qa,Ya,Fh,d0,u0,_a,Cr,Nr,Cd=ua(()=>{Tc="187",$i={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},oi={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},ep=0,Yh=1,np=2,Pr=1,ip=2,ls=3,ci=0,Ge=1,kn=2,va=0,hs=1,Jh=2,Kh=3,Zh=4,ap=5,Ma=100,sp=101,rp=102,op=103,cp=104,lp=200,hp=201,dp=202,up=203,$h=204,Qh=205,fp=206,pp=207,mp=208,gp=209,bp=210,xp=211,yp=212,_p=213,vp=214,Yo=0,Jo=1,Ko=2,Ka=3,Zo=4,$o=5,Qo=6,tc=7,Ic=0,Mp=1,Sp=2,li=0,td=1,ed=2,nd=3,id=4,ad=5,sd=6,rd=7,od=300,Sa=301,ds=302,Rc=303,Cc=304,ec=1e3,si=1001,nc=1002,we=1003,wp=1004,Lr=1005,fn=1006,Nc=1007,Pi=1008,en=1009,Dr=1010,Ur=1011,Qi=1012,us=1013,Mn=1014,pn=1015,Zn=1016,Pc=1017,Lc=1018,wa=1020,cd=35902,ld=35899,hd=1021,dd=1022,mn=1023,Ii=1026,Li=1027,Or=1028,Aa=1029,hi=1030,fs=1031,ps=1033,Fr=33776,Br=33777,kr=33778,zr=33779,Dc=35840,Uc=35841,Oc=35842,Fc=35843,Bc=36196,kc=37492,zc=37496,Vc=37488,Hc=37489,Vr=37490,Gc=37491,Wc=37808,jc=37809,Xc=37810,qc=37811,Yc=37812,Jc=37813,Kc=37814,Zc=37815,$c=37816,Qc=37817,tl=37818,el=37819,nl=37820,il=37821,al=36492,sl=36494,rl=36495,ol=36283,cl=36284,Hr=36285,ll=36286,tr=2300,ic=2301,Xo=2302,Bh=2303,kh=2400,zh=2401,Vh=2402,Ap=3200,hl=0,Ep=1,Di="",En="srgb",er="srgb-linear",nr="linear",ie="srgb",qo=7680,Tp=519,Ip=512,Rp=513,Cp=514,ud=515,Np=516,Pp=517,fd=518,pd=519,md=35044,gd="300 es",Fn=2e3,Za=2001;xf={},$a=null;Op={[Yo]:Yo,[Ko]:Qo,[Zo]:Zo,[Ka]:$o,[Jo]:Jo,[Qo]:Ko,[tc]:tc,[$o]:Ka},Yn=class{addEventListener(t,e){this._listeners===void 0&&(this._listeners={});let n=this._listeners;n[t]===void 0&&(n[t]=[]),n[t].indexOf(e)===-1&&n[t].push(e)}hasEventListener(t,e){let n=this._listeners;return n===void 0?!1:n[t]!==void 0&&n[t].indexOf(e)!==-1}removeEventListener(t,e){let n=this._listeners;if(n===void 0)return;let a=n[t];if(a!==void 0){let s=a.indexOf(e);s!==-1&&a.splice(s,1)}}dispatchEvent(t){let e=this._listeners;if(e===void 0)return;let n=e[t.type];if(n!==void 0){t.target=this;let a=n.slice(0);for(let s=0,r=a.length;s<r;s++)a[s].call(this,t);t.target=null}}},Ze=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],yf=1234567,$s=Math.PI/180,Qa=180/Math.PI;Ea={DEG2RAD:$s,RAD2DEG:Qa,generateUUID:ta,clamp:Bt,euclideanModulo:bd,mapLinear:ux,inverseLerp:fx,lerp:Qs,damp:px,pingpong:mx,smoothstep:gx,smootherstep:bx,randInt:xx,randFloat:yx,randFloatSpread:_x,seededRandom:vx,degToRad:Mx,radToDeg:Sx,isPowerOfTwo:wx,ceilPowerOfTwo:Ax,floorPowerOfTwo:xd,setQuaternionFromProperEuler:Ex,normalize:_d,denormalize:yd},Ad=class Ad{constructor(t=0,e=0){this.x=t,this.y=e}get width(){return this.x}set width(t){this.x=t}get height(){return this.y}set height(t){this.y=t}set(t,e){return this.x=t,this.y=e,this}setScalar(t){return this.x=t,this.y=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;default:throw new Error("THREE.Vector2: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y)}copy(t){return this.x=t.x,this.y=t.y,this}add(t){return this.x+=t.x,this.y+=t.y,this}addScalar(t){return this.x+=t,this.y+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this}subScalar(t){return this.x-=t,this.y-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this}multiply(t){return this.x*=t.x,this.y*=t.y,this}multiplyScalar(t){return this.x*=t,this.y*=t,this}divide(t){return this.x/=t.x,this.y/=t.y,this}divideScalar(t){return this.multiplyScalar(1/t)}applyMatrix3(t){let e=this.x,n=this.y,a=t.elements;return this.x=a[0]*e+a[3]*n+a[6],this.y=a[1]*e+a[4]*n+a[7],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this}clamp(t,e){return this.x=Bt(this.x,t.x,e.x),this.y=Bt(this.y,t.y,e.y),this}clampScalar(t,e){return this.x=Bt(this.x,t,e),this.y=Bt(this.y,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Bt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(t){return this.x*t.x+this.y*t.y}cross(t){return this.x*t.y-this.y*t.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(t){let e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;let n=this.dot(t)/e;return Math.acos(Bt(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){let e=this.x-t.x,n=this.y-t.y;return e*e+n*n}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this}equals(t){return t.x===this.x&&t.y===this.y}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this}rotateAround(t,e){let n=Math.cos(e),a=Math.sin(e),s=this.x-t.x,r=this.y-t.y;return this.x=s*n-r*a+t.x,this.y=s*a+r*n+t.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};Ad.prototype.isVector2=!0;Ct=Ad,Tn=class{constructor(t=0,e=0,n=0,a=1){this.isQuaternion=!0,this._x=t,this._y=e,this._z=n,this._w=a}static slerpFlat(t,e,n,a,s,r,o){let c=n[a+0],l=n[a+1],h=n[a+2],u=n[a+3],d=s[r+0],f=s[r+1],m=s[r+2],y=s[r+3];if(u!==y||c!==d||l!==f||h!==m){let g=c*d+l*f+h*m+u*y;g<0&&(d=-d,f=-f,m=-m,y=-y,g=-g);let b=1-o;if(g<.9995){let v=Math.acos(g),w=Math.sin(v);b=Math.sin(b*v)/w,o=Math.sin(o*v)/w,c=c*b+d*o,l=l*b+f*o,h=h*b+m*o,u=u*b+y*o}else{c=c*b+d*o,l=l*b+f*o,h=h*b+m*o,u=u*b+y*o;let v=1/Math.sqrt(c*c+l*l+h*h+u*u);c*=v,l*=v,h*=v,u*=v}}t[e]=c,t[e+1]=l,t[e+2]=h,t[e+3]=u}static multiplyQuaternionsFlat(t,e,n,a,s,r){let o=n[a],c=n[a+1],l=n[a+2],h=n[a+3],u=s[r],d=s[r+1],f=s[r+2],m=s[r+3];return t[e]=o*m+h*u+c*f-l*d,t[e+1]=c*m+h*d+l*u-o*f,t[e+2]=l*m+h*f+o*d-c*u,t[e+3]=h*m-o*u-c*d-l*f,t}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get w(){return this._w}set w(t){this._w=t,this._onChangeCallback()}set(t,e,n,a){return this._x=t,this._y=e,this._z=n,this._w=a,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(t){return this._x=t.x,this._y=t.y,this._z=t.z,this._w=t.w,this._onChangeCallback(),this}setFromEuler(t,e=!0){let n=t._x,a=t._y,s=t._z,r=t._order,o=Math.cos,c=Math.sin,l=o(n/2),h=o(a/2),u=o(s/2),d=c(n/2),f=c(a/2),m=c(s/2);switch(r){case"XYZ":this._x=d*h*u+l*f*m,this._y=l*f*u-d*h*m,this._z=l*h*m+d*f*u,this._w=l*h*u-d*f*m;break;case"YXZ":this._x=d*h*u+l*f*m,this._y=l*f*u-d*h*m,this._z=l*h*m-d*f*u,this._w=l*h*u+d*f*m;break;case"ZXY":this._x=d*h*u-l*f*m,this._y=l*f*u+d*h*m,this._z=l*h*m+d*f*u,this._w=l*h*u-d*f*m;break;case"ZYX":this._x=d*h*u-l*f*m,this._y=l*f*u+d*h*m,this._z=l*h*m-d*f*u,this._w=l*h*u+d*f*m;break;case"YZX":this._x=d*h*u+l*f*m,this._y=l*f*u+d*h*m,this._z=l*h*m-d*f*u,this._w=l*h*u-d*f*m;break;case"XZY":this._x=d*h*u-l*f*m,this._y=l*f*u-d*h*m,this._z=l*h*m+d*f*u,this._w=l*h*u+d*f*m;break;default:Rt("Quaternion: .setFromEuler() encountered an unknown order: "+r)}return e===!0&&this._onChangeCallback(),this}setFromAxisAngle(t,e){let n=e/2,a=Math.sin(n);return this._x=t.x*a,this._y=t.y*a,this._z=t.z*a,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(t){let e=t.elements,n=e[0],a=e[4],s=e[8],r=e[1],o=e[5],c=e[9],l=e[2],h=e[6],u=e[10],d=n+o+u;if(d>0){let f=.5/Math.sqrt(d+1);this._w=.25/f,this._x=(h-c)*f,this._y=(s-l)*f,this._z=(r-a)*f}else if(n>o&&n>u){let f=2*Math.sqrt(1+n-o-u);this._w=(h-c)/f,this._x=.25*f,this._y=(a+r)/f,this._z=(s+l)/f}else if(o>u){let f=2*Math.sqrt(1+o-n-u);this._w=(s-l)/f,this._x=(a+r)/f,this._y=.25*f,this._z=(c+h)/f}else{let f=2*Math.sqrt(1+u-n-o);this._w=(r-a)/f,this._x=(s+l)/f,this._y=(c+h)/f,this._z=.25*f}return this._onChangeCallback(),this}setFromUnitVectors(t,e){let n=t.dot(e)+1;return n<1e-8?(n=0,Math.abs(t.x)>Math.abs(t.z)?(this._x=-t.y,this._y=t.x,this._z=0,this._w=n):(this._x=0,this._y=-t.z,this._z=t.y,this._w=n)):(this._x=t.y*e.z-t.z*e.y,this._y=t.z*e.x-t.x*e.z,this._z=t.x*e.y-t.y*e.x,this._w=n),this.normalize()}angleTo(t){return 2*Math.acos(Math.abs(Bt(this.dot(t),-1,1)))}rotateTowards(t,e){let n=this.angleTo(t);if(n===0)return this;let a=Math.min(1,e/n);return this.slerp(t,a),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(t){return this._x*t._x+this._y*t._y+this._z*t._z+this._w*t._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let t=this.length();return t===0?(this._x=0,this._y=0,this._z=0,this._w=1):(t=1/t,this._x=this._x*t,this._y=this._y*t,this._z=this._z*t,this._w=this._w*t),this._onChangeCallback(),this}multiply(t){return this.multiplyQuaternions(this,t)}premultiply(t){return this.multiplyQuaternions(t,this)}multiplyQuaternions(t,e){let n=t._x,a=t._y,s=t._z,r=t._w,o=e._x,c=e._y,l=e._z,h=e._w;return this._x=n*h+r*o+a*l-s*c,this._y=a*h+r*c+s*o-n*l,this._z=s*h+r*l+n*c-a*o,this._w=r*h-n*o-a*c-s*l,this._onChangeCallback(),this}slerp(t,e){let n=t._x,a=t._y,s=t._z,r=t._w,o=this.dot(t);o<0&&(n=-n,a=-a,s=-s,r=-r,o=-o);let c=1-e;if(o<.9995){let l=Math.acos(o),h=Math.sin(l);c=Math.sin(c*l)/h,e=Math.sin(e*l)/h,this._x=this._x*c+n*e,this._y=this._y*c+a*e,this._z=this._z*c+s*e,this._w=this._w*c+r*e,this._onChangeCallback()}else this._x=this._x*c+n*e,this._y=this._y*c+a*e,this._z=this._z*c+s*e,this._w=this._w*c+r*e,this.normalize();return this}slerpQuaternions(t,e,n){return this.copy(t).slerp(e,n)}random(){let t=2*Math.PI*Math.random(),e=2*Math.PI*Math.random(),n=Math.random(),a=Math.sqrt(1-n),s=Math.sqrt(n);return this.set(a*Math.sin(t),a*Math.cos(t),s*Math.sin(e),s*Math.cos(e))}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._w===this._w}fromArray(t,e=0){return this._x=t[e],this._y=t[e+1],this._z=t[e+2],this._w=t[e+3],this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._w,t}fromBufferAttribute(t,e){return this._x=t.getX(e),this._y=t.getY(e),this._z=t.getZ(e),this._w=t.getW(e),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},Ed=class Ed{constructor(t=0,e=0,n=0){this.x=t,this.y=e,this.z=n}set(t,e,n){return n===void 0&&(n=this.z),this.x=t,this.y=e,this.z=n,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;default:throw new Error("THREE.Vector3: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this}multiplyVectors(t,e){return this.x=t.x*e.x,this.y=t.y*e.y,this.z=t.z*e.z,this}applyEuler(t){return this.applyQuaternion(_f.setFromEuler(t))}applyAxisAngle(t,e){return this.applyQuaternion(_f.setFromAxisAngle(t,e))}applyMatrix3(t){let e=this.x,n=this.y,a=this.z,s=t.elements;return this.x=s[0]*e+s[3]*n+s[6]*a,this.y=s[1]*e+s[4]*n+s[7]*a,this.z=s[2]*e+s[5]*n+s[8]*a,this}applyNormalMatrix(t){return this.applyMatrix3(t).normalize()}applyMatrix4(t){let e=this.x,n=this.y,a=this.z,s=t.elements,r=1/(s[3]*e+s[7]*n+s[11]*a+s[15]);return this.x=(s[0]*e+s[4]*n+s[8]*a+s[12])*r,this.y=(s[1]*e+s[5]*n+s[9]*a+s[13])*r,this.z=(s[2]*e+s[6]*n+s[10]*a+s[14])*r,this}applyQuaternion(t){let e=this.x,n=this.y,a=this.z,s=t.x,r=t.y,o=t.z,c=t.w,l=2*(r*a-o*n),h=2*(o*e-s*a),u=2*(s*n-r*e);return this.x=e+c*l+r*u-o*h,this.y=n+c*h+o*l-s*u,this.z=a+c*u+s*h-r*l,this}project(t){return this.applyMatrix4(t.matrixWorldInverse).applyMatrix4(t.projectionMatrix)}unproject(t){return this.applyMatrix4(t.projectionMatrixInverse).applyMatrix4(t.matrixWorld)}transformDirection(t){let e=this.x,n=this.y,a=this.z,s=t.elements;return this.x=s[0]*e+s[4]*n+s[8]*a,this.y=s[1]*e+s[5]*n+s[9]*a,this.z=s[2]*e+s[6]*n+s[10]*a,this.normalize()}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this}divideScalar(t){return this.multiplyScalar(1/t)}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this}clamp(t,e){return this.x=Bt(this.x,t.x,e.x),this.y=Bt(this.y,t.y,e.y),this.z=Bt(this.z,t.z,e.z),this}clampScalar(t,e){return this.x=Bt(this.x,t,e),this.y=Bt(this.y,t,e),this.z=Bt(this.z,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Bt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this}cross(t){return this.crossVectors(this,t)}crossVectors(t,e){let n=t.x,a=t.y,s=t.z,r=e.x,o=e.y,c=e.z;return this.x=a*c-s*o,this.y=s*r-n*c,this.z=n*o-a*r,this}projectOnVector(t){let e=t.lengthSq();if(e===0)return this.set(0,0,0);let n=t.dot(this)/e;return this.copy(t).multiplyScalar(n)}projectOnPlane(t){return fh.copy(this).projectOnVector(t),this.sub(fh)}reflect(t){return this.sub(fh.copy(t).multiplyScalar(2*this.dot(t)))}angleTo(t){let e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;let n=this.dot(t)/e;return Math.acos(Bt(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){let e=this.x-t.x,n=this.y-t.y,a=this.z-t.z;return e*e+n*n+a*a}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)+Math.abs(this.z-t.z)}setFromSpherical(t){return this.setFromSphericalCoords(t.radius,t.phi,t.theta)}setFromSphericalCoords(t,e,n){let a=Math.sin(e)*t;return this.x=a*Math.sin(n),this.y=Math.cos(e)*t,this.z=a*Math.cos(n),this}setFromCylindrical(t){return this.setFromCylindricalCoords(t.radius,t.theta,t.y)}setFromCylindricalCoords(t,e,n){return this.x=t*Math.sin(e),this.y=n,this.z=t*Math.cos(e),this}setFromMatrixPosition(t){let e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this}setFromMatrixScale(t){let e=this.setFromMatrixColumn(t,0).length(),n=this.setFromMatrixColumn(t,1).length(),a=this.setFromMatrixColumn(t,2).length();return this.x=e,this.y=n,this.z=a,this}setFromMatrixColumn(t,e){return this.fromArray(t.elements,e*4)}setFromMatrix3Column(t,e){return this.fromArray(t.elements,e*3)}setFromEuler(t){return this.x=t._x,this.y=t._y,this.z=t._z,this}setFromColor(t){return this.x=t.r,this.y=t.g,this.z=t.b,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let t=Math.random()*Math.PI*2,e=Math.random()*2-1,n=Math.sqrt(1-e*e);return this.x=n*Math.cos(t),this.y=e,this.z=n*Math.sin(t),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};Ed.prototype.isVector3=!0;F=Ed,fh=new F,_f=new Tn,Td=class Td{constructor(t,e,n,a,s,r,o,c,l){this.elements=[1,0,0,0,1,0,0,0,1],t!==void 0&&this.set(t,e,n,a,s,r,o,c,l)}set(t,e,n,a,s,r,o,c,l){let h=this.elements;return h[0]=t,h[1]=a,h[2]=o,h[3]=e,h[4]=s,h[5]=c,h[6]=n,h[7]=r,h[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(t){let e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],this}extractBasis(t,e,n){return t.setFromMatrix3Column(this,0),e.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(t){let e=t.elements;return this.set(e[0],e[4],e[8],e[1],e[5],e[9],e[2],e[6],e[10]),this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){let n=t.elements,a=e.elements,s=this.elements,r=n[0],o=n[3],c=n[6],l=n[1],h=n[4],u=n[7],d=n[2],f=n[5],m=n[8],y=a[0],g=a[3],b=a[6],v=a[1],w=a[4],p=a[7],_=a[2],M=a[5],x=a[8];return s[0]=r*y+o*v+c*_,s[3]=r*g+o*w+c*M,s[6]=r*b+o*p+c*x,s[1]=l*y+h*v+u*_,s[4]=l*g+h*w+u*M,s[7]=l*b+h*p+u*x,s[2]=d*y+f*v+m*_,s[5]=d*g+f*w+m*M,s[8]=d*b+f*p+m*x,this}multiplyScalar(t){let e=this.elements;return e[0]*=t,e[3]*=t,e[6]*=t,e[1]*=t,e[4]*=t,e[7]*=t,e[2]*=t,e[5]*=t,e[8]*=t,this}determinant(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8];return e*r*h-e*o*l-n*s*h+n*o*c+a*s*l-a*r*c}invert(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8],u=h*r-o*l,d=o*c-h*s,f=l*s-r*c,m=e*u+n*d+a*f;if(m===0)return this.set(0,0,0,0,0,0,0,0,0);let y=1/m;return t[0]=u*y,t[1]=(a*l-h*n)*y,t[2]=(o*n-a*r)*y,t[3]=d*y,t[4]=(h*e-a*c)*y,t[5]=(a*s-o*e)*y,t[6]=f*y,t[7]=(n*c-l*e)*y,t[8]=(r*e-n*s)*y,this}transpose(){let t,e=this.elements;return t=e[1],e[1]=e[3],e[3]=t,t=e[2],e[2]=e[6],e[6]=t,t=e[5],e[5]=e[7],e[7]=t,this}getNormalMatrix(t){return this.setFromMatrix4(t).invert().transpose()}transposeIntoArray(t){let e=this.elements;return t[0]=e[0],t[1]=e[3],t[2]=e[6],t[3]=e[1],t[4]=e[4],t[5]=e[7],t[6]=e[2],t[7]=e[5],t[8]=e[8],this}setUvTransform(t,e,n,a,s,r,o){let c=Math.cos(s),l=Math.sin(s);return this.set(n*c,n*l,-n*(c*r+l*o)+r+t,-a*l,a*c,-a*(-l*r+c*o)+o+e,0,0,1),this}scale(t,e){return Zs("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(ph.makeScale(t,e)),this}rotate(t){return Zs("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(ph.makeRotation(-t)),this}translate(t,e){return Zs("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(ph.makeTranslation(t,e)),this}makeTranslation(t,e){return t.isVector2?this.set(1,0,t.x,0,1,t.y,0,0,1):this.set(1,0,t,0,1,e,0,0,1),this}makeRotation(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,n,e,0,0,0,1),this}makeScale(t,e){return this.set(t,0,0,0,e,0,0,0,1),this}equals(t){let e=this.elements,n=t.elements;for(let a=0;a<9;a++)if(e[a]!==n[a])return!1;return!0}fromArray(t,e=0){for(let n=0;n<9;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){let n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t}clone(){return new this.constructor().fromArray(this.elements)}};Td.prototype.isMatrix3=!0;Dt=Td,ph=new Dt,vf=new Dt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Mf=new Dt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);Gt=Tx();ac=class{static getDataURL(t,e="image/png"){if(/^data:/i.test(t.src)||typeof HTMLCanvasElement>"u")return t.src;let n;if(t instanceof HTMLCanvasElement)n=t;else{Da===void 0&&(Da=ir("canvas")),Da.width=t.width,Da.height=t.height;let a=Da.getContext("2d");t instanceof ImageData?a.putImageData(t,0,0):a.drawImage(t,0,0,t.width,t.height),n=Da}return n.toDataURL(e)}static sRGBToLinear(t){if(typeof HTMLImageElement<"u"&&t instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&t instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&t instanceof ImageBitmap){let e=ir("canvas");e.width=t.width,e.height=t.height;let n=e.getContext("2d");n.drawImage(t,0,0,t.width,t.height);let a=n.getImageData(0,0,t.width,t.height),s=a.data;for(let r=0;r<s.length;r++)s[r]=Ei(s[r]/255)*255;return n.putImageData(a,0,0),e}else if(t.data){let e=t.data.slice(0);for(let n=0;n<e.length;n++)e instanceof Uint8Array||e instanceof Uint8ClampedArray?e[n]=Math.floor(Ei(e[n]/255)*255):e[n]=Ei(e[n]);return{data:e,width:t.width,height:t.height}}else return Rt("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),t}},Ix=0,ts=class{constructor(t=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:Ix++}),this.uuid=ta(),this.data=t,this.dataReady=!0,this.version=0}getSize(t){let e=this.data;return typeof HTMLVideoElement<"u"&&e instanceof HTMLVideoElement?t.set(e.videoWidth,e.videoHeight,0):typeof VideoFrame<"u"&&e instanceof VideoFrame?t.set(e.displayWidth,e.displayHeight,0):e!==null?t.set(e.width||0,e.height||0,e.depth||0):t.set(0,0,0),t}set needsUpdate(t){t===!0&&this.version++}toJSON(t){let e=t===void 0||typeof t=="string";if(!e&&t.images[this.uuid]!==void 0)return t.images[this.uuid];let n={uuid:this.uuid,url:""},a=this.data;if(a!==null){let s;if(Array.isArray(a)){s=[];for(let r=0,o=a.length;r<o;r++)a[r].isDataTexture?s.push(mh(a[r].image)):s.push(mh(a[r]))}else s=mh(a);n.url=s}return e||(t.images[this.uuid]=n),n}};Rx=0,gh=new F,vn=class i extends Yn{constructor(t=i.DEFAULT_IMAGE,e=i.DEFAULT_MAPPING,n=si,a=si,s=fn,r=Pi,o=mn,c=en,l=i.DEFAULT_ANISOTROPY,h=Di){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:Rx++}),this.uuid=ta(),this.name="",this.source=new ts(t),this.mipmaps=[],this.mapping=e,this.channel=0,this.wrapS=n,this.wrapT=a,this.magFilter=s,this.minFilter=r,this.anisotropy=l,this.format=o,this.internalFormat=null,this.type=c,this.offset=new Ct(0,0),this.repeat=new Ct(1,1),this.center=new Ct(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new Dt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(t&&t.depth&&t.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(gh).x}get height(){return this.source.getSize(gh).y}get depth(){return this.source.getSize(gh).z}get image(){return this.source.data}set image(t){this.source.data=t}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(t){return this.name=t.name,this.source=t.source,this.mipmaps=t.mipmaps.slice(0),this.mapping=t.mapping,this.channel=t.channel,this.wrapS=t.wrapS,this.wrapT=t.wrapT,this.magFilter=t.magFilter,this.minFilter=t.minFilter,this.anisotropy=t.anisotropy,this.format=t.format,this.internalFormat=t.internalFormat,this.type=t.type,this.normalized=t.normalized,this.offset.copy(t.offset),this.repeat.copy(t.repeat),this.center.copy(t.center),this.rotation=t.rotation,this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrix.copy(t.matrix),this.generateMipmaps=t.generateMipmaps,this.mipmapsAutoUpdate=t.mipmapsAutoUpdate,this.premultiplyAlpha=t.premultiplyAlpha,this.flipY=t.flipY,this.unpackAlignment=t.unpackAlignment,this.colorSpace=t.colorSpace,this.renderTarget=t.renderTarget,this.isRenderTargetTexture=t.isRenderTargetTexture,this.isPMREMTexture=t.isPMREMTexture,this.isArrayTexture=t.isArrayTexture,this.userData=JSON.parse(JSON.stringify(t.userData)),this.needsUpdate=!0,this}setValues(t){for(let e in t){let n=t[e];if(n===void 0){Rt(`Texture.setValues(): parameter '${e}' has value of undefined.`);continue}let a=this[e];if(a===void 0){Rt(`Texture.setValues(): property '${e}' does not exist.`);continue}a&&n&&a.isVector2&&n.isVector2||a&&n&&a.isVector3&&n.isVector3||a&&n&&a.isMatrix3&&n.isMatrix3?a.copy(n):this[e]=n}}toJSON(t){let e=t===void 0||typeof t=="string";if(!e&&t.textures[this.uuid]!==void 0)return t.textures[this.uuid];let n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(t).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),e||(t.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(t){if(this.mapping!==od)return t;if(t.applyMatrix3(this.matrix),t.x<0||t.x>1)switch(this.wrapS){case ec:t.x=t.x-Math.floor(t.x);break;case si:t.x=t.x<0?0:1;break;case nc:Math.abs(Math.floor(t.x)%2)===1?t.x=Math.ceil(t.x)-t.x:t.x=t.x-Math.floor(t.x);break}if(t.y<0||t.y>1)switch(this.wrapT){case ec:t.y=t.y-Math.floor(t.y);break;case si:t.y=t.y<0?0:1;break;case nc:Math.abs(Math.floor(t.y)%2)===1?t.y=Math.ceil(t.y)-t.y:t.y=t.y-Math.floor(t.y);break}return this.flipY&&(t.y=1-t.y),t}set needsUpdate(t){t===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(t){t===!0&&this.pmremVersion++}};vn.DEFAULT_IMAGE=null;vn.DEFAULT_MAPPING=od;vn.DEFAULT_ANISOTROPY=1;Id=class Id{constructor(t=0,e=0,n=0,a=1){this.x=t,this.y=e,this.z=n,this.w=a}get width(){return this.z}set width(t){this.z=t}get height(){return this.w}set height(t){this.w=t}set(t,e,n,a){return this.x=t,this.y=e,this.z=n,this.w=a,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this.w=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setW(t){return this.w=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;case 3:this.w=e;break;default:throw new Error("THREE.Vector4: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this.w=t.w!==void 0?t.w:1,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this.w+=t.w,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this.w+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this.w=t.w+e.w,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this.w+=t.w*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this.w-=t.w,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this.w-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this.w=t.w-e.w,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this.w*=t.w,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this.w*=t,this}applyMatrix4(t){let e=this.x,n=this.y,a=this.z,s=this.w,r=t.elements;return this.x=r[0]*e+r[4]*n+r[8]*a+r[12]*s,this.y=r[1]*e+r[5]*n+r[9]*a+r[13]*s,this.z=r[2]*e+r[6]*n+r[10]*a+r[14]*s,this.w=r[3]*e+r[7]*n+r[11]*a+r[15]*s,this}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this.w/=t.w,this}divideScalar(t){return this.multiplyScalar(1/t)}setAxisAngleFromQuaternion(t){this.w=2*Math.acos(t.w);let e=Math.sqrt(1-t.w*t.w);return e<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=t.x/e,this.y=t.y/e,this.z=t.z/e),this}setAxisAngleFromRotationMatrix(t){let e,n,a,s,c=t.elements,l=c[0],h=c[4],u=c[8],d=c[1],f=c[5],m=c[9],y=c[2],g=c[6],b=c[10];if(Math.abs(h-d)<.01&&Math.abs(u-y)<.01&&Math.abs(m-g)<.01){if(Math.abs(h+d)<.1&&Math.abs(u+y)<.1&&Math.abs(m+g)<.1&&Math.abs(l+f+b-3)<.1)return this.set(1,0,0,0),this;e=Math.PI;let w=(l+1)/2,p=(f+1)/2,_=(b+1)/2,M=(h+d)/4,x=(u+y)/4,S=(m+g)/4;return w>p&&w>_?w<.01?(n=0,a=.707106781,s=.707106781):(n=Math.sqrt(w),a=M/n,s=x/n):p>_?p<.01?(n=.707106781,a=0,s=.707106781):(a=Math.sqrt(p),n=M/a,s=S/a):_<.01?(n=.707106781,a=.707106781,s=0):(s=Math.sqrt(_),n=x/s,a=S/s),this.set(n,a,s,e),this}let v=Math.sqrt((g-m)*(g-m)+(u-y)*(u-y)+(d-h)*(d-h));return Math.abs(v)<.001&&(v=1),this.x=(g-m)/v,this.y=(u-y)/v,this.z=(d-h)/v,this.w=Math.acos((l+f+b-1)/2),this}setFromMatrixPosition(t){let e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this.w=e[15],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this.w=Math.min(this.w,t.w),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this.w=Math.max(this.w,t.w),this}clamp(t,e){return this.x=Bt(this.x,t.x,e.x),this.y=Bt(this.y,t.y,e.y),this.z=Bt(this.z,t.z,e.z),this.w=Bt(this.w,t.w,e.w),this}clampScalar(t,e){return this.x=Bt(this.x,t,e),this.y=Bt(this.y,t,e),this.z=Bt(this.z,t,e),this.w=Bt(this.w,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Bt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z+this.w*t.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this.w+=(t.w-this.w)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this.w=t.w+(e.w-t.w)*n,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z&&t.w===this.w}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this.w=t[e+3],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t[e+3]=this.w,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this.w=t.getW(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};Id.prototype.isVector4=!0;$t=Id,sc=class extends Yn{constructor(t=1,e=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:fn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=t,this.height=e,this.depth=n.depth,this.scissor=new $t(0,0,t,e),this.scissorTest=!1,this.viewport=new $t(0,0,t,e),this.textures=[];let a=n.count;for(let s=0;s<a;s++)this.textures[s]=new vn({width:t,height:e,depth:n.depth}),this.textures[s].isRenderTargetTexture=!0,this.textures[s].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(t={}){let e={minFilter:fn,generateMipmaps:!1,flipY:!1,internalFormat:null};t.mapping!==void 0&&(e.mapping=t.mapping),t.wrapS!==void 0&&(e.wrapS=t.wrapS),t.wrapT!==void 0&&(e.wrapT=t.wrapT),t.wrapR!==void 0&&(e.wrapR=t.wrapR),t.magFilter!==void 0&&(e.magFilter=t.magFilter),t.minFilter!==void 0&&(e.minFilter=t.minFilter),t.format!==void 0&&(e.format=t.format),t.type!==void 0&&(e.type=t.type),t.anisotropy!==void 0&&(e.anisotropy=t.anisotropy),t.colorSpace!==void 0&&(e.colorSpace=t.colorSpace),t.flipY!==void 0&&(e.flipY=t.flipY),t.generateMipmaps!==void 0&&(e.generateMipmaps=t.generateMipmaps),t.mipmapsAutoUpdate!==void 0&&(e.mipmapsAutoUpdate=t.mipmapsAutoUpdate),t.internalFormat!==void 0&&(e.internalFormat=t.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(e)}get texture(){return this.textures[0]}set texture(t){this.textures[0]=t}set depthTexture(t){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),t!==null&&t.renderTarget===null&&(t.renderTarget=this),this._depthTexture=t}get depthTexture(){return this._depthTexture}setSize(t,e,n=1){if(this.width!==t||this.height!==e||this.depth!==n){this.width=t,this.height=e,this.depth=n;for(let a=0,s=this.textures.length;a<s;a++)this.textures[a].image.width=t,this.textures[a].image.height=e,this.textures[a].image.depth=n,this.textures[a].isData3DTexture!==!0&&(this.textures[a].isArrayTexture=this.textures[a].image.depth>1);this.dispose()}this.viewport.set(0,0,t,e),this.scissor.set(0,0,t,e)}clone(){return new this.constructor().copy(this)}copy(t){this.width=t.width,this.height=t.height,this.depth=t.depth,this.scissor.copy(t.scissor),this.scissorTest=t.scissorTest,this.viewport.copy(t.viewport),this.textures.length=0;for(let e=0,n=t.textures.length;e<n;e++){this.textures[e]=t.textures[e].clone(),this.textures[e].isRenderTargetTexture=!0,this.textures[e].renderTarget=this;let a=Object.assign({},t.textures[e].image);this.textures[e].source=new ts(a)}if(this.depthBuffer=t.depthBuffer,this.stencilBuffer=t.stencilBuffer,this.resolveColorBuffer=t.resolveColorBuffer,this.resolveDepthBuffer=t.resolveDepthBuffer,this.resolveStencilBuffer=t.resolveStencilBuffer,this.storeMultisampledColorBuffer=t.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=t.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=t.storeMultisampledStencilBuffer,t.depthTexture!==null)if(t.depthTexture.renderTarget===t){let e=t.depthTexture.clone();e.renderTarget=null,this.depthTexture=e}else this.depthTexture=t.depthTexture;else this.depthTexture=null;return this.samples=t.samples,this.multiview=t.multiview,this.useArrayDepthTexture=t.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},In=class extends sc{constructor(t=1,e=1,n={}){super(t,e,n),this.isWebGLRenderTarget=!0}},sr=class extends vn{constructor(t=null,e=1,n=1,a=1){super(null),this.isDataArrayTexture=!0,this.image={data:t,width:e,height:n,depth:a},this.magFilter=we,this.minFilter=we,this.wrapR=si,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}addLayerUpdate(t){this.layerUpdates.add(t)}clearLayerUpdates(){this.layerUpdates.clear()}},rc=class extends vn{constructor(t=null,e=1,n=1,a=1){super(null),this.isData3DTexture=!0,this.image={data:t,width:e,height:n,depth:a},this.magFilter=we,this.minFilter=we,this.wrapR=si,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}},Ec=class Ec{constructor(t,e,n,a,s,r,o,c,l,h,u,d,f,m,y,g){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],t!==void 0&&this.set(t,e,n,a,s,r,o,c,l,h,u,d,f,m,y,g)}set(t,e,n,a,s,r,o,c,l,h,u,d,f,m,y,g){let b=this.elements;return b[0]=t,b[4]=e,b[8]=n,b[12]=a,b[1]=s,b[5]=r,b[9]=o,b[13]=c,b[2]=l,b[6]=h,b[10]=u,b[14]=d,b[3]=f,b[7]=m,b[11]=y,b[15]=g,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Ec().fromArray(this.elements)}copy(t){let e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],e[9]=n[9],e[10]=n[10],e[11]=n[11],e[12]=n[12],e[13]=n[13],e[14]=n[14],e[15]=n[15],this}copyPosition(t){let e=this.elements,n=t.elements;return e[12]=n[12],e[13]=n[13],e[14]=n[14],this}setFromMatrix3(t){let e=t.elements;return this.set(e[0],e[3],e[6],0,e[1],e[4],e[7],0,e[2],e[5],e[8],0,0,0,0,1),this}extractBasis(t,e,n){return this.determinantAffine()===0?(t.set(1,0,0),e.set(0,1,0),n.set(0,0,1),this):(t.setFromMatrixColumn(this,0),e.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(t,e,n){return this.set(t.x,e.x,n.x,0,t.y,e.y,n.y,0,t.z,e.z,n.z,0,0,0,0,1),this}extractRotation(t){if(t.determinantAffine()===0)return this.identity();let e=this.elements,n=t.elements,a=1/Ua.setFromMatrixColumn(t,0).length(),s=1/Ua.setFromMatrixColumn(t,1).length(),r=1/Ua.setFromMatrixColumn(t,2).length();return e[0]=n[0]*a,e[1]=n[1]*a,e[2]=n[2]*a,e[3]=0,e[4]=n[4]*s,e[5]=n[5]*s,e[6]=n[6]*s,e[7]=0,e[8]=n[8]*r,e[9]=n[9]*r,e[10]=n[10]*r,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromEuler(t){let e=this.elements,n=t.x,a=t.y,s=t.z,r=Math.cos(n),o=Math.sin(n),c=Math.cos(a),l=Math.sin(a),h=Math.cos(s),u=Math.sin(s);if(t.order==="XYZ"){let d=r*h,f=r*u,m=o*h,y=o*u;e[0]=c*h,e[4]=-c*u,e[8]=l,e[1]=f+m*l,e[5]=d-y*l,e[9]=-o*c,e[2]=y-d*l,e[6]=m+f*l,e[10]=r*c}else if(t.order==="YXZ"){let d=c*h,f=c*u,m=l*h,y=l*u;e[0]=d+y*o,e[4]=m*o-f,e[8]=r*l,e[1]=r*u,e[5]=r*h,e[9]=-o,e[2]=f*o-m,e[6]=y+d*o,e[10]=r*c}else if(t.order==="ZXY"){let d=c*h,f=c*u,m=l*h,y=l*u;e[0]=d-y*o,e[4]=-r*u,e[8]=m+f*o,e[1]=f+m*o,e[5]=r*h,e[9]=y-d*o,e[2]=-r*l,e[6]=o,e[10]=r*c}else if(t.order==="ZYX"){let d=r*h,f=r*u,m=o*h,y=o*u;e[0]=c*h,e[4]=m*l-f,e[8]=d*l+y,e[1]=c*u,e[5]=y*l+d,e[9]=f*l-m,e[2]=-l,e[6]=o*c,e[10]=r*c}else if(t.order==="YZX"){let d=r*c,f=r*l,m=o*c,y=o*l;e[0]=c*h,e[4]=y-d*u,e[8]=m*u+f,e[1]=u,e[5]=r*h,e[9]=-o*h,e[2]=-l*h,e[6]=f*u+m,e[10]=d-y*u}else if(t.order==="XZY"){let d=r*c,f=r*l,m=o*c,y=o*l;e[0]=c*h,e[4]=-u,e[8]=l*h,e[1]=d*u+y,e[5]=r*h,e[9]=f*u-m,e[2]=m*u-f,e[6]=o*h,e[10]=y*u+d}return e[3]=0,e[7]=0,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromQuaternion(t){return this.compose(Cx,t,Nx)}lookAt(t,e,n){let a=this.elements;return wn.subVectors(t,e),wn.lengthSq()===0&&(wn.z=1),wn.normalize(),Gi.crossVectors(n,wn),Gi.lengthSq()===0&&(Math.abs(n.z)===1?wn.x+=1e-4:wn.z+=1e-4,wn.normalize(),Gi.crossVectors(n,wn)),Gi.normalize(),yo.crossVectors(wn,Gi),a[0]=Gi.x,a[4]=yo.x,a[8]=wn.x,a[1]=Gi.y,a[5]=yo.y,a[9]=wn.y,a[2]=Gi.z,a[6]=yo.z,a[10]=wn.z,this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){let n=t.elements,a=e.elements,s=this.elements,r=n[0],o=n[4],c=n[8],l=n[12],h=n[1],u=n[5],d=n[9],f=n[13],m=n[2],y=n[6],g=n[10],b=n[14],v=n[3],w=n[7],p=n[11],_=n[15],M=a[0],x=a[4],S=a[8],E=a[12],A=a[1],R=a[5],C=a[9],L=a[13],N=a[2],U=a[6],z=a[10],B=a[14],K=a[3],W=a[7],Y=a[11],tt=a[15];return s[0]=r*M+o*A+c*N+l*K,s[4]=r*x+o*R+c*U+l*W,s[8]=r*S+o*C+c*z+l*Y,s[12]=r*E+o*L+c*B+l*tt,s[1]=h*M+u*A+d*N+f*K,s[5]=h*x+u*R+d*U+f*W,s[9]=h*S+u*C+d*z+f*Y,s[13]=h*E+u*L+d*B+f*tt,s[2]=m*M+y*A+g*N+b*K,s[6]=m*x+y*R+g*U+b*W,s[10]=m*S+y*C+g*z+b*Y,s[14]=m*E+y*L+g*B+b*tt,s[3]=v*M+w*A+p*N+_*K,s[7]=v*x+w*R+p*U+_*W,s[11]=v*S+w*C+p*z+_*Y,s[15]=v*E+w*L+p*B+_*tt,this}multiplyScalar(t){let e=this.elements;return e[0]*=t,e[4]*=t,e[8]*=t,e[12]*=t,e[1]*=t,e[5]*=t,e[9]*=t,e[13]*=t,e[2]*=t,e[6]*=t,e[10]*=t,e[14]*=t,e[3]*=t,e[7]*=t,e[11]*=t,e[15]*=t,this}determinant(){let t=this.elements,e=t[0],n=t[4],a=t[8],s=t[12],r=t[1],o=t[5],c=t[9],l=t[13],h=t[2],u=t[6],d=t[10],f=t[14],m=t[3],y=t[7],g=t[11],b=t[15],v=c*f-l*d,w=o*f-l*u,p=o*d-c*u,_=r*f-l*h,M=r*d-c*h,x=r*u-o*h;return e*(y*v-g*w+b*p)-n*(m*v-g*_+b*M)+a*(m*w-y*_+b*x)-s*(m*p-y*M+g*x)}determinantAffine(){let t=this.elements,e=t[0],n=t[4],a=t[8],s=t[1],r=t[5],o=t[9],c=t[2],l=t[6],h=t[10];return e*(r*h-o*l)-n*(s*h-o*c)+a*(s*l-r*c)}transpose(){let t=this.elements,e;return e=t[1],t[1]=t[4],t[4]=e,e=t[2],t[2]=t[8],t[8]=e,e=t[6],t[6]=t[9],t[9]=e,e=t[3],t[3]=t[12],t[12]=e,e=t[7],t[7]=t[13],t[13]=e,e=t[11],t[11]=t[14],t[14]=e,this}setPosition(t,e,n){let a=this.elements;return t.isVector3?(a[12]=t.x,a[13]=t.y,a[14]=t.z):(a[12]=t,a[13]=e,a[14]=n),this}invert(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8],u=t[9],d=t[10],f=t[11],m=t[12],y=t[13],g=t[14],b=t[15],v=e*o-n*r,w=e*c-a*r,p=e*l-s*r,_=n*c-a*o,M=n*l-s*o,x=a*l-s*c,S=h*y-u*m,E=h*g-d*m,A=h*b-f*m,R=u*g-d*y,C=u*b-f*y,L=d*b-f*g,N=v*L-w*C+p*R+_*A-M*E+x*S;if(N===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let U=1/N;return t[0]=(o*L-c*C+l*R)*U,t[1]=(a*C-n*L-s*R)*U,t[2]=(y*x-g*M+b*_)*U,t[3]=(d*M-u*x-f*_)*U,t[4]=(c*A-r*L-l*E)*U,t[5]=(e*L-a*A+s*E)*U,t[6]=(g*p-m*x-b*w)*U,t[7]=(h*x-d*p+f*w)*U,t[8]=(r*C-o*A+l*S)*U,t[9]=(n*A-e*C-s*S)*U,t[10]=(m*M-y*p+b*v)*U,t[11]=(u*p-h*M-f*v)*U,t[12]=(o*E-r*R-c*S)*U,t[13]=(e*R-n*E+a*S)*U,t[14]=(y*w-m*_-g*v)*U,t[15]=(h*_-u*w+d*v)*U,this}scale(t){let e=this.elements,n=t.x,a=t.y,s=t.z;return e[0]*=n,e[4]*=a,e[8]*=s,e[1]*=n,e[5]*=a,e[9]*=s,e[2]*=n,e[6]*=a,e[10]*=s,e[3]*=n,e[7]*=a,e[11]*=s,this}getMaxScaleOnAxis(){let t=this.elements,e=t[0]*t[0]+t[1]*t[1]+t[2]*t[2],n=t[4]*t[4]+t[5]*t[5]+t[6]*t[6],a=t[8]*t[8]+t[9]*t[9]+t[10]*t[10];return Math.sqrt(Math.max(e,n,a))}makeTranslation(t,e,n){return t.isVector3?this.set(1,0,0,t.x,0,1,0,t.y,0,0,1,t.z,0,0,0,1):this.set(1,0,0,t,0,1,0,e,0,0,1,n,0,0,0,1),this}makeRotationX(t){let e=Math.cos(t),n=Math.sin(t);return this.set(1,0,0,0,0,e,-n,0,0,n,e,0,0,0,0,1),this}makeRotationY(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,0,n,0,0,1,0,0,-n,0,e,0,0,0,0,1),this}makeRotationZ(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,0,n,e,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(t,e){let n=Math.cos(e),a=Math.sin(e),s=1-n,r=t.x,o=t.y,c=t.z,l=s*r,h=s*o;return this.set(l*r+n,l*o-a*c,l*c+a*o,0,l*o+a*c,h*o+n,h*c-a*r,0,l*c-a*o,h*c+a*r,s*c*c+n,0,0,0,0,1),this}makeScale(t,e,n){return this.set(t,0,0,0,0,e,0,0,0,0,n,0,0,0,0,1),this}makeShear(t,e,n,a,s,r){return this.set(1,n,s,0,t,1,r,0,e,a,1,0,0,0,0,1),this}compose(t,e,n){let a=this.elements,s=e._x,r=e._y,o=e._z,c=e._w,l=s+s,h=r+r,u=o+o,d=s*l,f=s*h,m=s*u,y=r*h,g=r*u,b=o*u,v=c*l,w=c*h,p=c*u,_=n.x,M=n.y,x=n.z;return a[0]=(1-(y+b))*_,a[1]=(f+p)*_,a[2]=(m-w)*_,a[3]=0,a[4]=(f-p)*M,a[5]=(1-(d+b))*M,a[6]=(g+v)*M,a[7]=0,a[8]=(m+w)*x,a[9]=(g-v)*x,a[10]=(1-(d+y))*x,a[11]=0,a[12]=t.x,a[13]=t.y,a[14]=t.z,a[15]=1,this}decompose(t,e,n){let a=this.elements;t.x=a[12],t.y=a[13],t.z=a[14];let s=this.determinantAffine();if(s===0)return n.set(1,1,1),e.identity(),this;let r=Ua.set(a[0],a[1],a[2]).length(),o=Ua.set(a[4],a[5],a[6]).length(),c=Ua.set(a[8],a[9],a[10]).length();s<0&&(r=-r),jn.copy(this);let l=1/r,h=1/o,u=1/c;return jn.elements[0]*=l,jn.elements[1]*=l,jn.elements[2]*=l,jn.elements[4]*=h,jn.elements[5]*=h,jn.elements[6]*=h,jn.elements[8]*=u,jn.elements[9]*=u,jn.elements[10]*=u,e.setFromRotationMatrix(jn),n.x=r,n.y=o,n.z=c,this}makePerspective(t,e,n,a,s,r,o=Fn,c=!1){let l=this.elements,h=2*s/(e-t),u=2*s/(n-a),d=(e+t)/(e-t),f=(n+a)/(n-a),m,y;if(c)m=s/(r-s),y=r*s/(r-s);else if(o===Fn)m=-(r+s)/(r-s),y=-2*r*s/(r-s);else if(o===Za)m=-r/(r-s),y=-r*s/(r-s);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=d,l[12]=0,l[1]=0,l[5]=u,l[9]=f,l[13]=0,l[2]=0,l[6]=0,l[10]=m,l[14]=y,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(t,e,n,a,s,r,o=Fn,c=!1){let l=this.elements,h=2/(e-t),u=2/(n-a),d=-(e+t)/(e-t),f=-(n+a)/(n-a),m,y;if(c)m=1/(r-s),y=r/(r-s);else if(o===Fn)m=-2/(r-s),y=-(r+s)/(r-s);else if(o===Za)m=-1/(r-s),y=-s/(r-s);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=0,l[12]=d,l[1]=0,l[5]=u,l[9]=0,l[13]=f,l[2]=0,l[6]=0,l[10]=m,l[14]=y,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(t){let e=this.elements,n=t.elements;for(let a=0;a<16;a++)if(e[a]!==n[a])return!1;return!0}fromArray(t,e=0){for(let n=0;n<16;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){let n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t[e+9]=n[9],t[e+10]=n[10],t[e+11]=n[11],t[e+12]=n[12],t[e+13]=n[13],t[e+14]=n[14],t[e+15]=n[15],t}};Ec.prototype.isMatrix4=!0;Zt=Ec,Ua=new F,jn=new Zt,Cx=new F(0,0,0),Nx=new F(1,1,1),Gi=new F,yo=new F,wn=new F,Sf=new Zt,wf=new Tn,Ri=class i{constructor(t=0,e=0,n=0,a=i.DEFAULT_ORDER){this.isEuler=!0,this._x=t,this._y=e,this._z=n,this._order=a}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get order(){return this._order}set order(t){this._order=t,this._onChangeCallback()}set(t,e,n,a=this._order){return this._x=t,this._y=e,this._z=n,this._order=a,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(t){return this._x=t._x,this._y=t._y,this._z=t._z,this._order=t._order,this._onChangeCallback(),this}setFromRotationMatrix(t,e=this._order,n=!0){let a=t.elements,s=a[0],r=a[4],o=a[8],c=a[1],l=a[5],h=a[9],u=a[2],d=a[6],f=a[10];switch(e){case"XYZ":this._y=Math.asin(Bt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,f),this._z=Math.atan2(-r,s)):(this._x=Math.atan2(d,l),this._z=0);break;case"YXZ":this._x=Math.asin(-Bt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,f),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-u,s),this._z=0);break;case"ZXY":this._x=Math.asin(Bt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(-u,f),this._z=Math.atan2(-r,l)):(this._y=0,this._z=Math.atan2(c,s));break;case"ZYX":this._y=Math.asin(-Bt(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(d,f),this._z=Math.atan2(c,s)):(this._x=0,this._z=Math.atan2(-r,l));break;case"YZX":this._z=Math.asin(Bt(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-h,l),this._y=Math.atan2(-u,s)):(this._x=0,this._y=Math.atan2(o,f));break;case"XZY":this._z=Math.asin(-Bt(r,-1,1)),Math.abs(r)<.9999999?(this._x=Math.atan2(d,l),this._y=Math.atan2(o,s)):(this._x=Math.atan2(-h,f),this._y=0);break;default:Rt("Euler: .setFromRotationMatrix() encountered an unknown order: "+e)}return this._order=e,n===!0&&this._onChangeCallback(),this}setFromQuaternion(t,e,n){return Sf.makeRotationFromQuaternion(t),this.setFromRotationMatrix(Sf,e,n)}setFromVector3(t,e=this._order){return this.set(t.x,t.y,t.z,e)}reorder(t){return wf.setFromEuler(this),this.setFromQuaternion(wf,t)}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._order===this._order}fromArray(t){return this._x=t[0],this._y=t[1],this._z=t[2],t[3]!==void 0&&(this._order=t[3]),this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._order,t}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};Ri.DEFAULT_ORDER="XYZ";es=class{constructor(){this.mask=1}set(t){this.mask=(1<<t|0)>>>0}enable(t){this.mask|=1<<t|0}enableAll(){this.mask=-1}toggle(t){this.mask^=1<<t|0}disable(t){this.mask&=~(1<<t|0)}disableAll(){this.mask=0}test(t){return(this.mask&t.mask)!==0}isEnabled(t){return(this.mask&(1<<t|0))!==0}},Px=0,Af=new F,Oa=new Tn,_i=new Zt,_o=new F,Xs=new F,Lx=new F,Dx=new Tn,Ef=new F(1,0,0),Tf=new F(0,1,0),If=new F(0,0,1),Rf={type:"added"},Ux={type:"removed"},Fa={type:"childadded",child:null},bh={type:"childremoved",child:null},Re=class i extends Yn{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Px++}),this.uuid=ta(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=i.DEFAULT_UP.clone();let t=new F,e=new Ri,n=new Tn,a=new F(1,1,1);function s(){n.setFromEuler(e,!1)}function r(){e.setFromQuaternion(n,void 0,!1)}e._onChange(s),n._onChange(r),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:t},rotation:{configurable:!0,enumerable:!0,value:e},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:a},modelViewMatrix:{value:new Zt},normalMatrix:{value:new Dt}}),this.matrix=new Zt,this.matrixWorld=new Zt,this.matrixAutoUpdate=i.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=i.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new es,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(t){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(t),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(t){return this.quaternion.premultiply(t),this}setRotationFromAxisAngle(t,e){this.quaternion.setFromAxisAngle(t,e)}setRotationFromEuler(t){this.quaternion.setFromEuler(t,!0)}setRotationFromMatrix(t){this.quaternion.setFromRotationMatrix(t)}setRotationFromQuaternion(t){this.quaternion.copy(t)}rotateOnAxis(t,e){return Oa.setFromAxisAngle(t,e),this.quaternion.multiply(Oa),this}rotateOnWorldAxis(t,e){return Oa.setFromAxisAngle(t,e),this.quaternion.premultiply(Oa),this}rotateX(t){return this.rotateOnAxis(Ef,t)}rotateY(t){return this.rotateOnAxis(Tf,t)}rotateZ(t){return this.rotateOnAxis(If,t)}translateOnAxis(t,e){return Af.copy(t).applyQuaternion(this.quaternion),this.position.add(Af.multiplyScalar(e)),this}translateX(t){return this.translateOnAxis(Ef,t)}translateY(t){return this.translateOnAxis(Tf,t)}translateZ(t){return this.translateOnAxis(If,t)}localToWorld(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(this.matrixWorld)}worldToLocal(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(_i.copy(this.matrixWorld).invert())}lookAt(t,e,n){t.isVector3?_o.copy(t):_o.set(t,e,n);let a=this.parent;this.updateWorldMatrix(!0,!1),Xs.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?_i.lookAt(Xs,_o,this.up):_i.lookAt(_o,Xs,this.up),this.quaternion.setFromRotationMatrix(_i),a&&(_i.extractRotation(a.matrixWorld),Oa.setFromRotationMatrix(_i),this.quaternion.premultiply(Oa.invert()))}add(t){if(arguments.length>1){for(let e=0;e<arguments.length;e++)this.add(arguments[e]);return this}return t===this?(Lt("Object3D.add: object can't be added as a child of itself.",t),this):(t&&t.isObject3D?(t.removeFromParent(),t.parent=this,this.children.push(t),t.dispatchEvent(Rf),Fa.child=t,this.dispatchEvent(Fa),Fa.child=null):Lt("Object3D.add: object not an instance of THREE.Object3D.",t),this)}remove(t){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}let e=this.children.indexOf(t);return e!==-1&&(t.parent=null,this.children.splice(e,1),t.dispatchEvent(Ux),bh.child=t,this.dispatchEvent(bh),bh.child=null),this}removeFromParent(){let t=this.parent;return t!==null&&t.remove(this),this}clear(){return this.remove(...this.children)}attach(t){return this.updateWorldMatrix(!0,!1),_i.copy(this.matrixWorld).invert(),t.parent!==null&&(t.parent.updateWorldMatrix(!0,!1),_i.multiply(t.parent.matrixWorld)),t.applyMatrix4(_i),t.removeFromParent(),t.parent=this,this.children.push(t),t.updateWorldMatrix(!1,!0),t.dispatchEvent(Rf),Fa.child=t,this.dispatchEvent(Fa),Fa.child=null,this}getObjectById(t){return this.getObjectByProperty("id",t)}getObjectByName(t){return this.getObjectByProperty("name",t)}getObjectByProperty(t,e){if(this[t]===e)return this;for(let n=0,a=this.children.length;n<a;n++){let r=this.children[n].getObjectByProperty(t,e);if(r!==void 0)return r}}getObjectsByProperty(t,e,n=[]){this[t]===e&&n.push(this);let a=this.children;for(let s=0,r=a.length;s<r;s++)a[s].getObjectsByProperty(t,e,n);return n}getWorldPosition(t){return this.updateWorldMatrix(!0,!1),t.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Xs,t,Lx),t}getWorldScale(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Xs,Dx,t),t}getWorldDirection(t){this.updateWorldMatrix(!0,!1);let e=this.matrixWorld.elements;return t.set(e[8],e[9],e[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(t){t(this);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].traverse(t)}traverseVisible(t){if(this.visible===!1)return;t(this);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].traverseVisible(t)}traverseAncestors(t){let e=this.parent;e!==null&&(t(e),e.traverseAncestors(t))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let t=this.pivot;if(t!==null){let e=t.x,n=t.y,a=t.z,s=this.matrix.elements;s[12]+=e-s[0]*e-s[4]*n-s[8]*a,s[13]+=n-s[1]*e-s[5]*n-s[9]*a,s[14]+=a-s[2]*e-s[6]*n-s[10]*a}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(t){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||t)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,t=!0);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].updateMatrixWorld(t)}updateWorldMatrix(t,e,n=!1){let a=this.parent;if(t===!0&&a!==null&&a.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),e===!0){let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].updateWorldMatrix(!1,!0,n)}}toJSON(t){let e=t===void 0||typeof t=="string",n={};e&&(t={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let a={};a.uuid=this.uuid,a.type=this.type,a.name=this.name,a.castShadow=this.castShadow,a.receiveShadow=this.receiveShadow,a.visible=this.visible,a.frustumCulled=this.frustumCulled,a.renderOrder=this.renderOrder,a.static=this.static,a.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(a.userData=this.userData),a.layers=this.layers.mask,a.matrix=this.matrix.toArray(),a.up=this.up.toArray(),this.pivot!==null&&(a.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(a.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(a.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(a.type="InstancedMesh",a.count=this.count,a.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(a.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(a.type="BatchedMesh",a.perObjectFrustumCulled=this.perObjectFrustumCulled,a.sortObjects=this.sortObjects,a.drawRanges=this._drawRanges,a.reservedRanges=this._reservedRanges,a.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),a.instanceInfo=this._instanceInfo.map(o=>({...o})),a.availableInstanceIds=this._availableInstanceIds.slice(),a.availableGeometryIds=this._availableGeometryIds.slice(),a.nextIndexStart=this._nextIndexStart,a.nextVertexStart=this._nextVertexStart,a.geometryCount=this._geometryCount,a.maxInstanceCount=this._maxInstanceCount,a.maxVertexCount=this._maxVertexCount,a.maxIndexCount=this._maxIndexCount,a.geometryInitialized=this._geometryInitialized,a.matricesTexture=this._matricesTexture.toJSON(t),a.indirectTexture=this._indirectTexture.toJSON(t),this._colorsTexture!==null&&(a.colorsTexture=this._colorsTexture.toJSON(t)),this.boundingSphere!==null&&(a.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(a.boundingBox=this.boundingBox.toJSON()));function s(o,c){return o[c.uuid]===void 0&&(o[c.uuid]=c.toJSON(t)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?a.background=this.background.toJSON():this.background.isTexture&&(a.background=this.background.toJSON(t).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(a.environment=this.environment.toJSON(t).uuid);else if(this.isMesh||this.isLine||this.isPoints){a.geometry=s(t.geometries,this.geometry);let o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){let c=o.shapes;if(Array.isArray(c))for(let l=0,h=c.length;l<h;l++){let u=c[l];s(t.shapes,u)}else s(t.shapes,c)}}if(this.isSkinnedMesh&&(a.bindMode=this.bindMode,a.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(s(t.skeletons,this.skeleton),a.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let o=[];for(let c=0,l=this.material.length;c<l;c++)o.push(s(t.materials,this.material[c]));a.material=o}else a.material=s(t.materials,this.material);if(this.children.length>0){a.children=[];for(let o=0;o<this.children.length;o++)a.children.push(this.children[o].toJSON(t).object)}if(this.animations.length>0){a.animations=[];for(let o=0;o<this.animations.length;o++){let c=this.animations[o];a.animations.push(s(t.animations,c))}}if(e){let o=r(t.geometries),c=r(t.materials),l=r(t.textures),h=r(t.images),u=r(t.shapes),d=r(t.skeletons),f=r(t.animations),m=r(t.nodes);o.length>0&&(n.geometries=o),c.length>0&&(n.materials=c),l.length>0&&(n.textures=l),h.length>0&&(n.images=h),u.length>0&&(n.shapes=u),d.length>0&&(n.skeletons=d),f.length>0&&(n.animations=f),m.length>0&&(n.nodes=m)}return n.object=a,n;function r(o){let c=[];for(let l in o){let h=o[l];delete h.metadata,c.push(h)}return c}}clone(t){return new this.constructor().copy(this,t)}copy(t,e=!0){if(this.name=t.name,this.up.copy(t.up),this.position.copy(t.position),this.rotation.order=t.rotation.order,this.quaternion.copy(t.quaternion),this.scale.copy(t.scale),this.pivot=t.pivot!==null?t.pivot.clone():null,this.matrix.copy(t.matrix),this.matrixWorld.copy(t.matrixWorld),this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrixWorldAutoUpdate=t.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=t.matrixWorldNeedsUpdate,this.layers.mask=t.layers.mask,this.visible=t.visible,this.castShadow=t.castShadow,this.receiveShadow=t.receiveShadow,this.frustumCulled=t.frustumCulled,this.renderOrder=t.renderOrder,this.static=t.static,this.animations=t.animations.slice(),this.userData=JSON.parse(JSON.stringify(t.userData)),e===!0)for(let n=0;n<t.children.length;n++){let a=t.children[n];this.add(a.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};Re.DEFAULT_UP=new F(0,1,0);Re.DEFAULT_MATRIX_AUTO_UPDATE=!0;Re.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;Ai=class extends Re{constructor(){super(),this.isGroup=!0,this.type="Group"}},Ox={type:"move"},ns=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Ai,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Ai,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new F,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new F),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Ai,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new F,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new F,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(t){return this._targetRay!==null&&this._targetRay.dispatchEvent(t),this._grip!==null&&this._grip.dispatchEvent(t),this._hand!==null&&this._hand.dispatchEvent(t),this}connect(t){if(t&&t.hand){let e=this._hand;if(e)for(let n of t.hand.values())this._getHandJoint(e,n)}return this.dispatchEvent({type:"connected",data:t}),this}disconnect(t){return this.dispatchEvent({type:"disconnected",data:t}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(t,e,n){let a=null,s=null,r=null,o=this._targetRay,c=this._grip,l=this._hand;if(t&&e.session.visibilityState!=="visible-blurred"){if(l&&t.hand){r=!0;for(let y of t.hand.values()){let g=e.getJointPose(y,n),b=this._getHandJoint(l,y);g!==null&&(b.matrix.fromArray(g.transform.matrix),b.matrix.decompose(b.position,b.quaternion,b.scale),b.matrixWorldNeedsUpdate=!0,b.jointRadius=g.radius),b.visible=g!==null}let h=l.joints["index-finger-tip"],u=l.joints["thumb-tip"],d=h.position.distanceTo(u.position),f=.02,m=.005;l.inputState.pinching&&d>f+m?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:t.handedness,target:this})):!l.inputState.pinching&&d<=f-m&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:t.handedness,target:this}))}else c!==null&&t.gripSpace&&(s=e.getPose(t.gripSpace,n),s!==null&&(c.matrix.fromArray(s.transform.matrix),c.matrix.decompose(c.position,c.quaternion,c.scale),c.matrixWorldNeedsUpdate=!0,s.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(s.linearVelocity)):c.hasLinearVelocity=!1,s.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(s.angularVelocity)):c.hasAngularVelocity=!1,c.eventsEnabled&&c.dispatchEvent({type:"gripUpdated",data:t,target:this})));o!==null&&(a=e.getPose(t.targetRaySpace,n),a===null&&s!==null&&(a=s),a!==null&&(o.matrix.fromArray(a.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,a.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(a.linearVelocity)):o.hasLinearVelocity=!1,a.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(a.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(Ox)))}return o!==null&&(o.visible=a!==null),c!==null&&(c.visible=s!==null),l!==null&&(l.visible=r!==null),this}_getHandJoint(t,e){if(t.joints[e.jointName]===void 0){let n=new Ai;n.matrixAutoUpdate=!1,n.visible=!1,t.joints[e.jointName]=n,t.add(n)}return t.joints[e.jointName]}},Fp={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Wi={h:0,s:0,l:0},vo={h:0,s:0,l:0};kt=class{constructor(t,e,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(t,e,n)}set(t,e,n){if(e===void 0&&n===void 0){let a=t;a&&a.isColor?this.copy(a):typeof a=="number"?this.setHex(a):typeof a=="string"&&this.setStyle(a)}else this.setRGB(t,e,n);return this}setScalar(t){return this.r=t,this.g=t,this.b=t,this}setHex(t,e=En){return t=Math.floor(t),this.r=(t>>16&255)/255,this.g=(t>>8&255)/255,this.b=(t&255)/255,Gt.colorSpaceToWorking(this,e),this}setRGB(t,e,n,a=Gt.workingColorSpace){return this.r=t,this.g=e,this.b=n,Gt.colorSpaceToWorking(this,a),this}setHSL(t,e,n,a=Gt.workingColorSpace){if(t=bd(t,1),e=Bt(e,0,1),n=Bt(n,0,1),e===0)this.r=this.g=this.b=n;else{let s=n<=.5?n*(1+e):n+e-n*e,r=2*n-s;this.r=xh(r,s,t+1/3),this.g=xh(r,s,t),this.b=xh(r,s,t-1/3)}return Gt.colorSpaceToWorking(this,a),this}setStyle(t,e=En){function n(s){s!==void 0&&parseFloat(s)<1&&Rt("Color: Alpha component of "+t+" will be ignored.")}let a;if(a=/^(\w+)\(([^\)]*)\)/.exec(t)){let s,r=a[1],o=a[2];switch(r){case"rgb":case"rgba":if(s=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(255,parseInt(s[1],10))/255,Math.min(255,parseInt(s[2],10))/255,Math.min(255,parseInt(s[3],10))/255,e);if(s=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(100,parseFloat(s[1]))/100,Math.min(100,parseFloat(s[2]))/100,Math.min(100,parseFloat(s[3]))/100,e);break;case"hsl":case"hsla":if(s=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setHSL(parseFloat(s[1])/360,parseFloat(s[2])/100,parseFloat(s[3])/100,e);break;default:Rt("Color: Unknown color model "+t)}}else if(a=/^\#([A-Fa-f\d]+)$/.exec(t)){let s=a[1],r=s.length;if(r===3)return this.setRGB(parseInt(s.charAt(0),16)/15,parseInt(s.charAt(1),16)/15,parseInt(s.charAt(2),16)/15,e);if(r===6)return this.setHex(parseInt(s,16),e);Rt("Color: Invalid hex color "+t)}else if(t&&t.length>0)return this.setColorName(t,e);return this}setColorName(t,e=En){let n=Fp[t.toLowerCase()];return n!==void 0?this.setHex(n,e):Rt("Color: Unknown color "+t),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(t){return this.r=t.r,this.g=t.g,this.b=t.b,this}copySRGBToLinear(t){return this.r=Ei(t.r),this.g=Ei(t.g),this.b=Ei(t.b),this}copyLinearToSRGB(t){return this.r=Ja(t.r),this.g=Ja(t.g),this.b=Ja(t.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(t=En){return Gt.workingToColorSpace($e.copy(this),t),Math.round(Bt($e.r*255,0,255))*65536+Math.round(Bt($e.g*255,0,255))*256+Math.round(Bt($e.b*255,0,255))}getHexString(t=En){return("000000"+this.getHex(t).toString(16)).slice(-6)}getHSL(t,e=Gt.workingColorSpace){Gt.workingToColorSpace($e.copy(this),e);let n=$e.r,a=$e.g,s=$e.b,r=Math.max(n,a,s),o=Math.min(n,a,s),c,l,h=(o+r)/2;if(o===r)c=0,l=0;else{let u=r-o;switch(l=h<=.5?u/(r+o):u/(2-r-o),r){case n:c=(a-s)/u+(a<s?6:0);break;case a:c=(s-n)/u+2;break;case s:c=(n-a)/u+4;break}c/=6}return t.h=c,t.s=l,t.l=h,t}getRGB(t,e=Gt.workingColorSpace){return Gt.workingToColorSpace($e.copy(this),e),t.r=$e.r,t.g=$e.g,t.b=$e.b,t}getStyle(t=En){Gt.workingToColorSpace($e.copy(this),t);let e=$e.r,n=$e.g,a=$e.b;return t!==En?`color(${t} ${e.toFixed(3)} ${n.toFixed(3)} ${a.toFixed(3)})`:`rgb(${Math.round(e*255)},${Math.round(n*255)},${Math.round(a*255)})`}offsetHSL(t,e,n){return this.getHSL(Wi),this.setHSL(Wi.h+t,Wi.s+e,Wi.l+n)}add(t){return this.r+=t.r,this.g+=t.g,this.b+=t.b,this}addColors(t,e){return this.r=t.r+e.r,this.g=t.g+e.g,this.b=t.b+e.b,this}addScalar(t){return this.r+=t,this.g+=t,this.b+=t,this}sub(t){return this.r=Math.max(0,this.r-t.r),this.g=Math.max(0,this.g-t.g),this.b=Math.max(0,this.b-t.b),this}multiply(t){return this.r*=t.r,this.g*=t.g,this.b*=t.b,this}multiplyScalar(t){return this.r*=t,this.g*=t,this.b*=t,this}lerp(t,e){return this.r+=(t.r-this.r)*e,this.g+=(t.g-this.g)*e,this.b+=(t.b-this.b)*e,this}lerpColors(t,e,n){return this.r=t.r+(e.r-t.r)*n,this.g=t.g+(e.g-t.g)*n,this.b=t.b+(e.b-t.b)*n,this}lerpHSL(t,e){this.getHSL(Wi),t.getHSL(vo);let n=Qs(Wi.h,vo.h,e),a=Qs(Wi.s,vo.s,e),s=Qs(Wi.l,vo.l,e);return this.setHSL(n,a,s),this}setFromVector3(t){return this.r=t.x,this.g=t.y,this.b=t.z,this}applyMatrix3(t){let e=this.r,n=this.g,a=this.b,s=t.elements;return this.r=s[0]*e+s[3]*n+s[6]*a,this.g=s[1]*e+s[4]*n+s[7]*a,this.b=s[2]*e+s[5]*n+s[8]*a,this}equals(t){return t.r===this.r&&t.g===this.g&&t.b===this.b}fromArray(t,e=0){return this.r=t[e],this.g=t[e+1],this.b=t[e+2],this}toArray(t=[],e=0){return t[e]=this.r,t[e+1]=this.g,t[e+2]=this.b,t}fromBufferAttribute(t,e){return this.r=t.getX(e),this.g=t.getY(e),this.b=t.getZ(e),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},$e=new kt;kt.NAMES=Fp;rr=class extends Re{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ri,this.environmentIntensity=1,this.environmentRotation=new Ri,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(t,e){return super.copy(t,e),this.background=t.background!==null?t.background.clone():null,this.environment=t.environment!==null?t.environment.clone():null,this.fog=t.fog!==null?t.fog.clone():null,this.backgroundBlurriness=t.backgroundBlurriness,this.backgroundIntensity=t.backgroundIntensity,this.backgroundRotation.copy(t.backgroundRotation),this.environmentIntensity=t.environmentIntensity,this.environmentRotation.copy(t.environmentRotation),this.overrideMaterial=t.overrideMaterial!==null?t.overrideMaterial.clone():null,this.matrixAutoUpdate=t.matrixAutoUpdate,this}toJSON(t){let e=super.toJSON(t);return this.fog!==null&&(e.object.fog=this.fog.toJSON()),e.object.backgroundBlurriness=this.backgroundBlurriness,e.object.backgroundIntensity=this.backgroundIntensity,e.object.backgroundRotation=this.backgroundRotation.toArray(),e.object.environmentIntensity=this.environmentIntensity,e.object.environmentRotation=this.environmentRotation.toArray(),e}},Xn=new F,vi=new F,yh=new F,Mi=new F,Ba=new F,ka=new F,Cf=new F,_h=new F,vh=new F,Mh=new F,Sh=new $t,wh=new $t,Ah=new $t,ai=class i{constructor(t=new F,e=new F,n=new F){this.a=t,this.b=e,this.c=n}static getNormal(t,e,n,a){a.subVectors(n,e),Xn.subVectors(t,e),a.cross(Xn);let s=a.lengthSq();return s>0?a.multiplyScalar(1/Math.sqrt(s)):a.set(0,0,0)}static getBarycoord(t,e,n,a,s){Xn.subVectors(a,e),vi.subVectors(n,e),yh.subVectors(t,e);let r=Xn.dot(Xn),o=Xn.dot(vi),c=Xn.dot(yh),l=vi.dot(vi),h=vi.dot(yh),u=r*l-o*o;if(u===0)return s.set(0,0,0),null;let d=1/u,f=(l*c-o*h)*d,m=(r*h-o*c)*d;return s.set(1-f-m,m,f)}static containsPoint(t,e,n,a){return this.getBarycoord(t,e,n,a,Mi)===null?!1:Mi.x>=0&&Mi.y>=0&&Mi.x+Mi.y<=1}static getInterpolation(t,e,n,a,s,r,o,c){return this.getBarycoord(t,e,n,a,Mi)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(s,Mi.x),c.addScaledVector(r,Mi.y),c.addScaledVector(o,Mi.z),c)}static getInterpolatedAttribute(t,e,n,a,s,r){return Sh.setScalar(0),wh.setScalar(0),Ah.setScalar(0),Sh.fromBufferAttribute(t,e),wh.fromBufferAttribute(t,n),Ah.fromBufferAttribute(t,a),r.setScalar(0),r.addScaledVector(Sh,s.x),r.addScaledVector(wh,s.y),r.addScaledVector(Ah,s.z),r}static isFrontFacing(t,e,n,a){return Xn.subVectors(n,e),vi.subVectors(t,e),Xn.cross(vi).dot(a)<0}set(t,e,n){return this.a.copy(t),this.b.copy(e),this.c.copy(n),this}setFromPointsAndIndices(t,e,n,a){return this.a.copy(t[e]),this.b.copy(t[n]),this.c.copy(t[a]),this}setFromAttributeAndIndices(t,e,n,a){return this.a.fromBufferAttribute(t,e),this.b.fromBufferAttribute(t,n),this.c.fromBufferAttribute(t,a),this}clone(){return new this.constructor().copy(this)}copy(t){return this.a.copy(t.a),this.b.copy(t.b),this.c.copy(t.c),this}getArea(){return Xn.subVectors(this.c,this.b),vi.subVectors(this.a,this.b),Xn.cross(vi).length()*.5}getMidpoint(t){return t.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(t){return i.getNormal(this.a,this.b,this.c,t)}getPlane(t){return t.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(t,e){return i.getBarycoord(t,this.a,this.b,this.c,e)}getInterpolation(t,e,n,a,s){return i.getInterpolation(t,this.a,this.b,this.c,e,n,a,s)}containsPoint(t){return i.containsPoint(t,this.a,this.b,this.c)}isFrontFacing(t){return i.isFrontFacing(this.a,this.b,this.c,t)}intersectsBox(t){return t.intersectsTriangle(this)}closestPointToPoint(t,e){let n=this.a,a=this.b,s=this.c,r,o;Ba.subVectors(a,n),ka.subVectors(s,n),_h.subVectors(t,n);let c=Ba.dot(_h),l=ka.dot(_h);if(c<=0&&l<=0)return e.copy(n);vh.subVectors(t,a);let h=Ba.dot(vh),u=ka.dot(vh);if(h>=0&&u<=h)return e.copy(a);let d=c*u-h*l;if(d<=0&&c>=0&&h<=0&&c-h>0)return r=c/(c-h),e.copy(n).addScaledVector(Ba,r);Mh.subVectors(t,s);let f=Ba.dot(Mh),m=ka.dot(Mh);if(m>=0&&f<=m)return e.copy(s);let y=f*l-c*m;if(y<=0&&l>=0&&m<=0)return o=l/(l-m),e.copy(n).addScaledVector(ka,o);let g=h*m-f*u;if(g<=0&&u-h>=0&&f-m>=0)return Cf.subVectors(s,a),o=(u-h)/(u-h+(f-m)),e.copy(a).addScaledVector(Cf,o);let b=1/(g+y+d);return r=y*b,o=d*b,e.copy(n).addScaledVector(Ba,r).addScaledVector(ka,o)}equals(t){return t.a.equals(this.a)&&t.b.equals(this.b)&&t.c.equals(this.c)}},Ie=class{constructor(t=new F(1/0,1/0,1/0),e=new F(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=t,this.max=e}set(t,e){return this.min.copy(t),this.max.copy(e),this}setFromArray(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e+=3)this.expandByPoint(qn.fromArray(t,e));return this}setFromBufferAttribute(t){this.makeEmpty();for(let e=0,n=t.count;e<n;e++)this.expandByPoint(qn.fromBufferAttribute(t,e));return this}setFromPoints(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e++)this.expandByPoint(t[e]);return this}setFromCenterAndSize(t,e){let n=qn.copy(e).multiplyScalar(.5);return this.min.copy(t).sub(n),this.max.copy(t).add(n),this}setFromObject(t,e=!1){return this.makeEmpty(),this.expandByObject(t,e)}clone(){return new this.constructor().copy(this)}copy(t){return this.min.copy(t.min),this.max.copy(t.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(t){return this.isEmpty()?t.set(0,0,0):t.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(t){return this.isEmpty()?t.set(0,0,0):t.subVectors(this.max,this.min)}expandByPoint(t){return this.min.min(t),this.max.max(t),this}expandByVector(t){return this.min.sub(t),this.max.add(t),this}expandByScalar(t){return this.min.addScalar(-t),this.max.addScalar(t),this}expandByObject(t,e=!1){t.updateWorldMatrix(!1,!1);let n=t.geometry;if(n!==void 0){let s=n.getAttribute("position");if(e===!0&&s!==void 0&&t.isInstancedMesh!==!0&&t.isBatchedMesh!==!0)for(let r=0,o=s.count;r<o;r++)t.isMesh===!0?t.getVertexPosition(r,qn):qn.fromBufferAttribute(s,r),qn.applyMatrix4(t.matrixWorld),this.expandByPoint(qn);else t.boundingBox!==void 0?(t.boundingBox===null&&t.computeBoundingBox(),Mo.copy(t.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),Mo.copy(n.boundingBox)),Mo.applyMatrix4(t.matrixWorld),this.union(Mo)}let a=t.children;for(let s=0,r=a.length;s<r;s++)this.expandByObject(a[s],e);return this}containsPoint(t){return t.x>=this.min.x&&t.x<=this.max.x&&t.y>=this.min.y&&t.y<=this.max.y&&t.z>=this.min.z&&t.z<=this.max.z}containsBox(t){return this.min.x<=t.min.x&&t.max.x<=this.max.x&&this.min.y<=t.min.y&&t.max.y<=this.max.y&&this.min.z<=t.min.z&&t.max.z<=this.max.z}getParameter(t,e){return e.set((t.x-this.min.x)/(this.max.x-this.min.x),(t.y-this.min.y)/(this.max.y-this.min.y),(t.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(t){return t.max.x>=this.min.x&&t.min.x<=this.max.x&&t.max.y>=this.min.y&&t.min.y<=this.max.y&&t.max.z>=this.min.z&&t.min.z<=this.max.z}intersectsSphere(t){return this.clampPoint(t.center,qn),qn.distanceToSquared(t.center)<=t.radius*t.radius}intersectsPlane(t){let e,n;return t.normal.x>0?(e=t.normal.x*this.min.x,n=t.normal.x*this.max.x):(e=t.normal.x*this.max.x,n=t.normal.x*this.min.x),t.normal.y>0?(e+=t.normal.y*this.min.y,n+=t.normal.y*this.max.y):(e+=t.normal.y*this.max.y,n+=t.normal.y*this.min.y),t.normal.z>0?(e+=t.normal.z*this.min.z,n+=t.normal.z*this.max.z):(e+=t.normal.z*this.max.z,n+=t.normal.z*this.min.z),e<=-t.constant&&n>=-t.constant}intersectsTriangle(t){if(this.isEmpty())return!1;this.getCenter(qs),So.subVectors(this.max,qs),za.subVectors(t.a,qs),Va.subVectors(t.b,qs),Ha.subVectors(t.c,qs),ji.subVectors(Va,za),Xi.subVectors(Ha,Va),fa.subVectors(za,Ha);let e=[0,-ji.z,ji.y,0,-Xi.z,Xi.y,0,-fa.z,fa.y,ji.z,0,-ji.x,Xi.z,0,-Xi.x,fa.z,0,-fa.x,-ji.y,ji.x,0,-Xi.y,Xi.x,0,-fa.y,fa.x,0];return!Eh(e,za,Va,Ha,So)||(e=[1,0,0,0,1,0,0,0,1],!Eh(e,za,Va,Ha,So))?!1:(wo.crossVectors(ji,Xi),e=[wo.x,wo.y,wo.z],Eh(e,za,Va,Ha,So))}clampPoint(t,e){return e.copy(t).clamp(this.min,this.max)}distanceToPoint(t){return this.clampPoint(t,qn).distanceTo(t)}getBoundingSphere(t){return this.isEmpty()?t.makeEmpty():(this.getCenter(t.center),t.radius=this.getSize(qn).length()*.5),t}intersect(t){return this.min.max(t.min),this.max.min(t.max),this.isEmpty()&&this.makeEmpty(),this}union(t){return this.min.min(t.min),this.max.max(t.max),this}applyMatrix4(t){return this.isEmpty()?this:(Si[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(t),Si[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(t),Si[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(t),Si[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(t),Si[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(t),Si[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(t),Si[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(t),Si[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(t),this.setFromPoints(Si),this)}translate(t){return this.min.add(t),this.max.add(t),this}equals(t){return t.min.equals(this.min)&&t.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(t){return this.min.fromArray(t.min),this.max.fromArray(t.max),this}},Si=[new F,new F,new F,new F,new F,new F,new F,new F],qn=new F,Mo=new Ie,za=new F,Va=new F,Ha=new F,ji=new F,Xi=new F,fa=new F,qs=new F,So=new F,wo=new F,pa=new F;Se=new F,Ao=new Ct,Fx=0,un=class extends Yn{constructor(t,e,n=!1){if(super(),Array.isArray(t))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:Fx++}),this.name="",this.array=t,this.itemSize=e,this.count=t!==void 0?t.length/e:0,this.normalized=n,this.usage=md,this.updateRanges=[],this.gpuType=pn,this.version=0,this._normalizationScale=t!==void 0?dl(t):void 0}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.name=t.name,this.array=new t.array.constructor(t.array),this.itemSize=t.itemSize,this.count=t.count,this.normalized=t.normalized,this.usage=t.usage,this.gpuType=t.gpuType,this._normalizationScale=t._normalizationScale,this}copyAt(t,e,n){t*=this.itemSize,n*=e.itemSize;for(let a=0,s=this.itemSize;a<s;a++)this.array[t+a]=e.array[n+a];return this}copyArray(t){return this.array.set(t),this}applyMatrix3(t){if(this.itemSize===2)for(let e=0,n=this.count;e<n;e++)Ao.fromBufferAttribute(this,e),Ao.applyMatrix3(t),this.setXY(e,Ao.x,Ao.y);else if(this.itemSize===3)for(let e=0,n=this.count;e<n;e++)Se.fromBufferAttribute(this,e),Se.applyMatrix3(t),this.setXYZ(e,Se.x,Se.y,Se.z);return this}applyMatrix4(t){for(let e=0,n=this.count;e<n;e++)Se.fromBufferAttribute(this,e),Se.applyMatrix4(t),this.setXYZ(e,Se.x,Se.y,Se.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)Se.fromBufferAttribute(this,e),Se.applyNormalMatrix(t),this.setXYZ(e,Se.x,Se.y,Se.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)Se.fromBufferAttribute(this,e),Se.transformDirection(t),this.setXYZ(e,Se.x,Se.y,Se.z);return this}set(t,e=0){return this.array.set(t,e),this}getComponent(t,e){let n=this.array[t*this.itemSize+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.array[t*this.itemSize+e]=n,this}getX(t){let e=this.array[t*this.itemSize];return this.normalized&&(e=this._denormalize(e)),e}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize]=e,this}getY(t){let e=this.array[t*this.itemSize+1];return this.normalized&&(e=this._denormalize(e)),e}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+1]=e,this}getZ(t){let e=this.array[t*this.itemSize+2];return this.normalized&&(e=this._denormalize(e)),e}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+2]=e,this}getW(t){let e=this.array[t*this.itemSize+3];return this.normalized&&(e=this._denormalize(e)),e}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+3]=e,this}setXY(t,e,n){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.array[t+0]=e,this.array[t+1]=n,this}setXYZ(t,e,n,a){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=a,this}setXYZW(t,e,n,a,s){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a),s=this._normalize(s)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=a,this.array[t+3]=s,this}onUpload(t){return this.onUploadCallback=t,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let t={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return t.name=this.name,t.usage=this.usage,t.gpuType=this.gpuType,t}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(t){let e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):yd(t,this.array)}_normalize(t){let e=this._normalizationScale;return e!==void 0?Math.round(t*e):_d(t,this.array)}},or=class extends un{constructor(t,e,n){super(new Uint16Array(t),e,n)}},cr=class extends un{constructor(t,e,n){super(new Uint32Array(t),e,n)}},re=class extends un{constructor(t,e,n){super(new Float32Array(t),e,n)}},Bx=new Ie,Ys=new F,Th=new F,ze=class{constructor(t=new F,e=-1){this.isSphere=!0,this.center=t,this.radius=e}set(t,e){return this.center.copy(t),this.radius=e,this}setFromPoints(t,e){let n=this.center;e!==void 0?n.copy(e):Bx.setFromPoints(t).getCenter(n);let a=0;for(let s=0,r=t.length;s<r;s++)a=Math.max(a,n.distanceToSquared(t[s]));return this.radius=Math.sqrt(a),this}copy(t){return this.center.copy(t.center),this.radius=t.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(t){return t.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(t){return t.distanceTo(this.center)-this.radius}intersectsSphere(t){let e=this.radius+t.radius;return t.center.distanceToSquared(this.center)<=e*e}intersectsBox(t){return t.intersectsSphere(this)}intersectsPlane(t){return Math.abs(t.distanceToPoint(this.center))<=this.radius}clampPoint(t,e){let n=this.center.distanceToSquared(t);return e.copy(t),n>this.radius*this.radius&&(e.sub(this.center).normalize(),e.multiplyScalar(this.radius).add(this.center)),e}getBoundingBox(t){return this.isEmpty()?(t.makeEmpty(),t):(t.set(this.center,this.center),t.expandByScalar(this.radius),t)}applyMatrix4(t){return this.center.applyMatrix4(t),this.radius=this.radius*t.getMaxScaleOnAxis(),this}translate(t){return this.center.add(t),this}expandByPoint(t){if(this.isEmpty())return this.center.copy(t),this.radius=0,this;Ys.subVectors(t,this.center);let e=Ys.lengthSq();if(e>this.radius*this.radius){let n=Math.sqrt(e),a=(n-this.radius)*.5;this.center.addScaledVector(Ys,a/n),this.radius+=a}return this}union(t){return t.isEmpty()?this:this.isEmpty()?(this.copy(t),this):(this.center.equals(t.center)===!0?this.radius=Math.max(this.radius,t.radius):(Th.subVectors(t.center,this.center).setLength(t.radius),this.expandByPoint(Ys.copy(t.center).add(Th)),this.expandByPoint(Ys.copy(t.center).sub(Th))),this)}equals(t){return t.center.equals(this.center)&&t.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(t){return this.radius=t.radius,this.center.fromArray(t.center),this}},kx=0,On=new Zt,Ih=new Re,Ga=new F,An=new Ie,Js=new Ie,ke=new F,Ae=class i extends Yn{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:kx++}),this.uuid=ta(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(t){return Array.isArray(t)?this.index=new(hx(t)?cr:or)(t,1):this.index=t,this}setIndirect(t,e=0){return this.indirect=t,this.indirectOffset=e,this}getIndirect(){return this.indirect}getAttribute(t){return this.attributes[t]}setAttribute(t,e){return this.attributes[t]=e,this}deleteAttribute(t){return delete this.attributes[t],this}hasAttribute(t){return this.attributes[t]!==void 0}addGroup(t,e,n=0){this.groups.push({start:t,count:e,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(t,e){this.drawRange.start=t,this.drawRange.count=e}applyMatrix4(t){let e=this.attributes.position;e!==void 0&&(e.applyMatrix4(t),e.needsUpdate=!0);let n=this.attributes.normal;if(n!==void 0){let s=new Dt().getNormalMatrix(t);n.applyNormalMatrix(s),n.needsUpdate=!0}let a=this.attributes.tangent;return a!==void 0&&(a.transformDirection(t),a.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(t){return On.makeRotationFromQuaternion(t),this.applyMatrix4(On),this}rotateX(t){return On.makeRotationX(t),this.applyMatrix4(On),this}rotateY(t){return On.makeRotationY(t),this.applyMatrix4(On),this}rotateZ(t){return On.makeRotationZ(t),this.applyMatrix4(On),this}translate(t,e,n){return On.makeTranslation(t,e,n),this.applyMatrix4(On),this}scale(t,e,n){return On.makeScale(t,e,n),this.applyMatrix4(On),this}lookAt(t){return Ih.lookAt(t),Ih.updateMatrix(),this.applyMatrix4(Ih.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Ga).negate(),this.translate(Ga.x,Ga.y,Ga.z),this}setFromPoints(t){let e=this.getAttribute("position");if(e===void 0){let n=[];for(let a=0,s=t.length;a<s;a++){let r=t[a];n.push(r.x,r.y,r.z||0)}this.setAttribute("position",new re(n,3))}else{let n=Math.min(t.length,e.count);for(let a=0;a<n;a++){let s=t[a];e.setXYZ(a,s.x,s.y,s.z||0)}t.length>e.count&&Rt("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),e.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ie);let t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){Lt("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new F(-1/0,-1/0,-1/0),new F(1/0,1/0,1/0));return}if(t!==void 0){if(this.boundingBox.setFromBufferAttribute(t),e)for(let n=0,a=e.length;n<a;n++){let s=e[n];An.setFromBufferAttribute(s),this.morphTargetsRelative?(ke.addVectors(this.boundingBox.min,An.min),this.boundingBox.expandByPoint(ke),ke.addVectors(this.boundingBox.max,An.max),this.boundingBox.expandByPoint(ke)):(this.boundingBox.expandByPoint(An.min),this.boundingBox.expandByPoint(An.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&Lt('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new ze);let t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){Lt("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new F,1/0);return}if(t){let n=this.boundingSphere.center;if(An.setFromBufferAttribute(t),e)for(let s=0,r=e.length;s<r;s++){let o=e[s];Js.setFromBufferAttribute(o),this.morphTargetsRelative?(ke.addVectors(An.min,Js.min),An.expandByPoint(ke),ke.addVectors(An.max,Js.max),An.expandByPoint(ke)):(An.expandByPoint(Js.min),An.expandByPoint(Js.max))}An.getCenter(n);let a=0;for(let s=0,r=t.count;s<r;s++)ke.fromBufferAttribute(t,s),a=Math.max(a,n.distanceToSquared(ke));if(e)for(let s=0,r=e.length;s<r;s++){let o=e[s],c=this.morphTargetsRelative;for(let l=0,h=o.count;l<h;l++)ke.fromBufferAttribute(o,l),c&&(Ga.fromBufferAttribute(t,l),ke.add(Ga)),a=Math.max(a,n.distanceToSquared(ke))}this.boundingSphere.radius=Math.sqrt(a),isNaN(this.boundingSphere.radius)&&Lt('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let t=this.index,e=this.attributes;if(t===null||e.position===void 0||e.normal===void 0||e.uv===void 0){Lt("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let n=e.position,a=e.normal,s=e.uv,r=this.getAttribute("tangent");(r===void 0||r.count!==n.count)&&(r=new un(new Float32Array(4*n.count),4),this.setAttribute("tangent",r));let o=[],c=[],l=new Uint8Array(n.count);for(let E=0;E<n.count;E++)o[E]=new F,c[E]=new F;let h=new F,u=new F,d=new F,f=new Ct,m=new Ct,y=new Ct,g=new F,b=new F;function v(E,A,R){l[E]=l[A]=l[R]=1,h.fromBufferAttribute(n,E),u.fromBufferAttribute(n,A),d.fromBufferAttribute(n,R),f.fromBufferAttribute(s,E),m.fromBufferAttribute(s,A),y.fromBufferAttribute(s,R),u.sub(h),d.sub(h),m.sub(f),y.sub(f);let C=1/(m.x*y.y-y.x*m.y);isFinite(C)&&(g.copy(u).multiplyScalar(y.y).addScaledVector(d,-m.y).multiplyScalar(C),b.copy(d).multiplyScalar(m.x).addScaledVector(u,-y.x).multiplyScalar(C),o[E].add(g),o[A].add(g),o[R].add(g),c[E].add(b),c[A].add(b),c[R].add(b))}let w=this.groups;w.length===0&&(w=[{start:0,count:t.count}]);for(let E=0,A=w.length;E<A;++E){let R=w[E],C=R.start,L=R.count;for(let N=C,U=C+L;N<U;N+=3)v(t.getX(N+0),t.getX(N+1),t.getX(N+2))}let p=new F,_=new F,M=new F,x=new F;function S(E){M.fromBufferAttribute(a,E),x.copy(M);let A=o[E];p.copy(A),p.sub(M.multiplyScalar(M.dot(A))).normalize(),_.crossVectors(x,A);let C=_.dot(c[E])<0?-1:1;r.setXYZW(E,p.x,p.y,p.z,C)}for(let E=0,A=n.count;E<A;++E)l[E]&&S(E);this._transformed=!0}computeVertexNormals(){let t=this.index,e=this.getAttribute("position");if(e!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==e.count)n=new un(new Float32Array(e.count*3),3),this.setAttribute("normal",n);else for(let d=0,f=n.count;d<f;d++)n.setXYZ(d,0,0,0);let a=new F,s=new F,r=new F,o=new F,c=new F,l=new F,h=new F,u=new F;if(t)for(let d=0,f=t.count;d<f;d+=3){let m=t.getX(d+0),y=t.getX(d+1),g=t.getX(d+2);a.fromBufferAttribute(e,m),s.fromBufferAttribute(e,y),r.fromBufferAttribute(e,g),h.subVectors(r,s),u.subVectors(a,s),h.cross(u),o.fromBufferAttribute(n,m),c.fromBufferAttribute(n,y),l.fromBufferAttribute(n,g),o.add(h),c.add(h),l.add(h),n.setXYZ(m,o.x,o.y,o.z),n.setXYZ(y,c.x,c.y,c.z),n.setXYZ(g,l.x,l.y,l.z)}else for(let d=0,f=e.count;d<f;d+=3)a.fromBufferAttribute(e,d+0),s.fromBufferAttribute(e,d+1),r.fromBufferAttribute(e,d+2),h.subVectors(r,s),u.subVectors(a,s),h.cross(u),n.setXYZ(d+0,h.x,h.y,h.z),n.setXYZ(d+1,h.x,h.y,h.z),n.setXYZ(d+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){let t=this.attributes.normal;for(let e=0,n=t.count;e<n;e++)ke.fromBufferAttribute(t,e),ke.normalize(),t.setXYZ(e,ke.x,ke.y,ke.z)}toNonIndexed(){function t(o,c){let l=o.array,h=o.itemSize,u=o.normalized,d=new l.constructor(c.length*h),f=0,m=0;for(let y=0,g=c.length;y<g;y++){o.isInterleavedBufferAttribute?f=c[y]*o.data.stride+o.offset:f=c[y]*h;for(let b=0;b<h;b++)d[m++]=l[f++]}return new un(d,h,u)}if(this.index===null)return Rt("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let e=new i,n=this.index.array,a=this.attributes;for(let o in a){let c=a[o],l=t(c,n);e.setAttribute(o,l)}let s=this.morphAttributes;for(let o in s){let c=[],l=s[o];for(let h=0,u=l.length;h<u;h++){let d=l[h],f=t(d,n);c.push(f)}e.morphAttributes[o]=c}e.morphTargetsRelative=this.morphTargetsRelative;let r=this.groups;for(let o=0,c=r.length;o<c;o++){let l=r[o];e.addGroup(l.start,l.count,l.materialIndex)}return e}toJSON(){let t={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(t.uuid=this.uuid,t.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,t.name=this.name,Object.keys(this.userData).length>0&&(t.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let c=this.parameters;for(let l in c)c[l]!==void 0&&(t[l]=c[l]);return t}t.data={attributes:{}};let e=this.index;e!==null&&(t.data.index={type:e.array.constructor.name,array:Array.prototype.slice.call(e.array)});let n=this.attributes;for(let c in n){let l=n[c];t.data.attributes[c]=l.toJSON(t.data)}let a={},s=!1;for(let c in this.morphAttributes){let l=this.morphAttributes[c],h=[];for(let u=0,d=l.length;u<d;u++){let f=l[u];h.push(f.toJSON(t.data))}h.length>0&&(a[c]=h,s=!0)}s&&(t.data.morphAttributes=a,t.data.morphTargetsRelative=this.morphTargetsRelative);let r=this.groups;r.length>0&&(t.data.groups=JSON.parse(JSON.stringify(r)));let o=this.boundingSphere;return o!==null&&(t.data.boundingSphere=o.toJSON()),t}clone(){return new this.constructor().copy(this)}copy(t){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let e={};this.name=t.name;let n=t.index;n!==null&&this.setIndex(n.clone());let a=t.attributes;for(let l in a){let h=a[l];this.setAttribute(l,h.clone(e))}let s=t.morphAttributes;for(let l in s){let h=[],u=s[l];for(let d=0,f=u.length;d<f;d++)h.push(u[d].clone(e));this.morphAttributes[l]=h}this.morphTargetsRelative=t.morphTargetsRelative;let r=t.groups;for(let l=0,h=r.length;l<h;l++){let u=r[l];this.addGroup(u.start,u.count,u.materialIndex)}let o=t.boundingBox;o!==null&&(this.boundingBox=o.clone());let c=t.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=t.drawRange.start,this.drawRange.count=t.drawRange.count,this.userData=t.userData,this._transformed=t._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}},oc=class{constructor(t,e){this.isInterleavedBuffer=!0,this.array=t,this.stride=e,this.count=t!==void 0?t.length/e:0,this.usage=md,this.updateRanges=[],this.version=0,this.uuid=ta()}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.array=new t.array.constructor(t.array),this.count=t.count,this.stride=t.stride,this.usage=t.usage,this}copyAt(t,e,n){t*=this.stride,n*=e.stride;for(let a=0,s=this.stride;a<s;a++)this.array[t+a]=e.array[n+a];return this}set(t,e=0){return this.array.set(t,e),this}clone(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});let e=Nf(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=this.array.slice(0).buffer);let n=new this.array.constructor(t.arrayBuffers[e]),a=new this.constructor(n,this.stride);return a.setUsage(this.usage),a}onUpload(t){return this.onUploadCallback=t,this}toJSON(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});let e=Nf(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=Array.from(new Uint32Array(this.array.slice(0).buffer)));let n={uuid:this.uuid,buffer:e,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}};ln=new F,Jn=class i{constructor(t,e,n,a=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=t,this.itemSize=e,this.offset=n,this.normalized=a,this._normalizationScale=t!==void 0?dl(t.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(t){this.data.needsUpdate=t}applyMatrix4(t){for(let e=0,n=this.data.count;e<n;e++)ln.fromBufferAttribute(this,e),ln.applyMatrix4(t),this.setXYZ(e,ln.x,ln.y,ln.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)ln.fromBufferAttribute(this,e),ln.applyNormalMatrix(t),this.setXYZ(e,ln.x,ln.y,ln.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)ln.fromBufferAttribute(this,e),ln.transformDirection(t),this.setXYZ(e,ln.x,ln.y,ln.z);return this}getComponent(t,e){let n=this.array[t*this.data.stride+this.offset+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.data.array[t*this.data.stride+this.offset+e]=n,this}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset]=e,this}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+1]=e,this}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+2]=e,this}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+3]=e,this}getX(t){let e=this.data.array[t*this.data.stride+this.offset];return this.normalized&&(e=this._denormalize(e)),e}getY(t){let e=this.data.array[t*this.data.stride+this.offset+1];return this.normalized&&(e=this._denormalize(e)),e}getZ(t){let e=this.data.array[t*this.data.stride+this.offset+2];return this.normalized&&(e=this._denormalize(e)),e}getW(t){let e=this.data.array[t*this.data.stride+this.offset+3];return this.normalized&&(e=this._denormalize(e)),e}setXY(t,e,n){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.data.array[t+0]=e,this.data.array[t+1]=n,this}setXYZ(t,e,n,a){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=a,this}setXYZW(t,e,n,a,s){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a),s=this._normalize(s)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=a,this.data.array[t+3]=s,this}clone(t){if(t===void 0){ar("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");let e=[];for(let n=0;n<this.count;n++){let a=n*this.data.stride+this.offset;for(let s=0;s<this.itemSize;s++)e.push(this.data.array[a+s])}return new un(new this.array.constructor(e),this.itemSize,this.normalized)}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.clone(t)),new i(t.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(t){if(t===void 0){ar("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");let e=[];for(let n=0;n<this.count;n++){let a=n*this.data.stride+this.offset;for(let s=0;s<this.itemSize;s++)e.push(this.data.array[a+s])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:e,normalized:this.normalized}}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.toJSON(t)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(t){let e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):yd(t,this.data.array)}_normalize(t){let e=this._normalizationScale;return e!==void 0?Math.round(t*e):_d(t,this.data.array)}},Rh=new F,zx=new F,Vx=new Dt,hn=class{constructor(t=new F(1,0,0),e=0){this.isPlane=!0,this.normal=t,this.constant=e}set(t,e){return this.normal.copy(t),this.constant=e,this}setComponents(t,e,n,a){return this.normal.set(t,e,n),this.constant=a,this}setFromNormalAndCoplanarPoint(t,e){return this.normal.copy(t),this.constant=-e.dot(this.normal),this}setFromCoplanarPoints(t,e,n){let a=Rh.subVectors(n,e).cross(zx.subVectors(t,e)).normalize();return this.setFromNormalAndCoplanarPoint(a,t),this}copy(t){return this.normal.copy(t.normal),this.constant=t.constant,this}normalize(){let t=1/this.normal.length();return this.normal.multiplyScalar(t),this.constant*=t,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(t){return this.normal.dot(t)+this.constant}distanceToSphere(t){return this.distanceToPoint(t.center)-t.radius}projectPoint(t,e){return e.copy(t).addScaledVector(this.normal,-this.distanceToPoint(t))}intersectLine(t,e,n=!0){let a=t.delta(Rh),s=this.normal.dot(a);if(s===0)return this.distanceToPoint(t.start)===0?e.copy(t.start):null;let r=-(t.start.dot(this.normal)+this.constant)/s;return n===!0&&(r<0||r>1)?null:e.copy(t.start).addScaledVector(a,r)}intersectsLine(t){let e=this.distanceToPoint(t.start),n=this.distanceToPoint(t.end);return e<0&&n>0||n<0&&e>0}intersectsBox(t){return t.intersectsPlane(this)}intersectsSphere(t){return t.intersectsPlane(this)}coplanarPoint(t){return t.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(t,e){let n=e||Vx.getNormalMatrix(t),a=this.coplanarPoint(Rh).applyMatrix4(t),s=this.normal.applyMatrix3(n).normalize();return this.constant=-a.dot(s),this}translate(t){return this.constant-=t.dot(this.normal),this}equals(t){return t.normal.equals(this.normal)&&t.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(t){return this.normal.fromArray(t.normal),this.constant=t.constant,this}},Hx=0,ri=class extends Yn{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:Hx++}),this.uuid=ta(),this.name="",this.type="Material",this.blending=hs,this.side=ci,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=$h,this.blendDst=Qh,this.blendEquation=Ma,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new kt(0,0,0),this.blendAlpha=0,this.depthFunc=Ka,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Tp,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=qo,this.stencilZFail=qo,this.stencilZPass=qo,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(t){this._alphaTest>0!=t>0&&this.version++,this._alphaTest=t}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(t){if(t!==void 0)for(let e in t){let n=t[e];if(n===void 0){Rt(`Material: parameter '${e}' has value of undefined.`);continue}let a=this[e];if(a===void 0){Rt(`Material: '${e}' is not a property of THREE.${this.type}.`);continue}a&&a.isColor?a.set(n):a&&a.isVector2&&n&&n.isVector2||a&&a.isEuler&&n&&n.isEuler||a&&a.isVector3&&n&&n.isVector3?a.copy(n):this[e]=n}}toJSON(t){let e=t===void 0||typeof t=="string";e&&(t={textures:{},images:{}});let n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(t).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(t).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(t).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(t).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(t).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(t).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(t).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(t).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(t).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(t).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(t).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(t).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(t).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(t).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(t).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(t).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(t).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(t).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(t).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(t).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(t).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(t).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(t).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(t).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(t).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(t).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(t).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(s=>s.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function a(s){let r=[];for(let o in s){let c=s[o];delete c.metadata,r.push(c)}return r}if(e){let s=a(t.textures),r=a(t.images);s.length>0&&(n.textures=s),r.length>0&&(n.images=r)}return n}fromJSON(t,e){if(t.uuid!==void 0&&(this.uuid=t.uuid),t.name!==void 0&&(this.name=t.name),t.color!==void 0&&this.color!==void 0&&this.color.setHex(t.color),t.roughness!==void 0&&(this.roughness=t.roughness),t.metalness!==void 0&&(this.metalness=t.metalness),t.sheen!==void 0&&(this.sheen=t.sheen),t.sheenColor!==void 0&&(this.sheenColor=new kt().setHex(t.sheenColor)),t.sheenRoughness!==void 0&&(this.sheenRoughness=t.sheenRoughness),t.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(t.emissive),t.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(t.specular),t.specularIntensity!==void 0&&(this.specularIntensity=t.specularIntensity),t.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(t.specularColor),t.shininess!==void 0&&(this.shininess=t.shininess),t.clearcoat!==void 0&&(this.clearcoat=t.clearcoat),t.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=t.clearcoatRoughness),t.diffuseRoughness!==void 0&&(this.diffuseRoughness=t.diffuseRoughness),t.dispersion!==void 0&&(this.dispersion=t.dispersion),t.retroreflectivity!==void 0&&(this.retroreflectivity=t.retroreflectivity),t.iridescence!==void 0&&(this.iridescence=t.iridescence),t.iridescenceIOR!==void 0&&(this.iridescenceIOR=t.iridescenceIOR),t.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessMinimum),t.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=t.iridescenceThicknessMaximum),t.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=t.iridescenceThicknessRange[1]),t.transmission!==void 0&&(this.transmission=t.transmission),t.thickness!==void 0&&(this.thickness=t.thickness),t.attenuationDistance!==void 0&&(this.attenuationDistance=t.attenuationDistance),t.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(t.attenuationColor),t.anisotropy!==void 0&&(this.anisotropy=t.anisotropy),t.anisotropyRotation!==void 0&&(this.anisotropyRotation=t.anisotropyRotation),t.fog!==void 0&&(this.fog=t.fog),t.flatShading!==void 0&&(this.flatShading=t.flatShading),t.blending!==void 0&&(this.blending=t.blending),t.combine!==void 0&&(this.combine=t.combine),t.side!==void 0&&(this.side=t.side),t.shadowSide!==void 0&&(this.shadowSide=t.shadowSide),t.opacity!==void 0&&(this.opacity=t.opacity),t.transparent!==void 0&&(this.transparent=t.transparent),t.alphaTest!==void 0&&(this.alphaTest=t.alphaTest),t.alphaHash!==void 0&&(this.alphaHash=t.alphaHash),t.depthFunc!==void 0&&(this.depthFunc=t.depthFunc),t.depthTest!==void 0&&(this.depthTest=t.depthTest),t.depthWrite!==void 0&&(this.depthWrite=t.depthWrite),t.colorWrite!==void 0&&(this.colorWrite=t.colorWrite),t.clippingPlanes!==void 0&&(this.clippingPlanes=t.clippingPlanes.map(n=>new hn().fromJSON(n))),t.clipIntersection!==void 0&&(this.clipIntersection=t.clipIntersection),t.clipShadows!==void 0&&(this.clipShadows=t.clipShadows),t.depthPacking!==void 0&&(this.depthPacking=t.depthPacking),t.blendSrc!==void 0&&(this.blendSrc=t.blendSrc),t.blendDst!==void 0&&(this.blendDst=t.blendDst),t.blendEquation!==void 0&&(this.blendEquation=t.blendEquation),t.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=t.blendSrcAlpha),t.blendDstAlpha!==void 0&&(this.blendDstAlpha=t.blendDstAlpha),t.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=t.blendEquationAlpha),t.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(t.blendColor),t.blendAlpha!==void 0&&(this.blendAlpha=t.blendAlpha),t.stencilWriteMask!==void 0&&(this.stencilWriteMask=t.stencilWriteMask),t.stencilFunc!==void 0&&(this.stencilFunc=t.stencilFunc),t.stencilRef!==void 0&&(this.stencilRef=t.stencilRef),t.stencilFuncMask!==void 0&&(this.stencilFuncMask=t.stencilFuncMask),t.stencilFail!==void 0&&(this.stencilFail=t.stencilFail),t.stencilZFail!==void 0&&(this.stencilZFail=t.stencilZFail),t.stencilZPass!==void 0&&(this.stencilZPass=t.stencilZPass),t.stencilWrite!==void 0&&(this.stencilWrite=t.stencilWrite),t.wireframe!==void 0&&(this.wireframe=t.wireframe),t.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=t.wireframeLinewidth),t.wireframeLinecap!==void 0&&(this.wireframeLinecap=t.wireframeLinecap),t.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=t.wireframeLinejoin),t.rotation!==void 0&&(this.rotation=t.rotation),t.linewidth!==void 0&&(this.linewidth=t.linewidth),t.linecap!==void 0&&(this.linecap=t.linecap),t.linejoin!==void 0&&(this.linejoin=t.linejoin),t.dashSize!==void 0&&(this.dashSize=t.dashSize),t.gapSize!==void 0&&(this.gapSize=t.gapSize),t.scale!==void 0&&(this.scale=t.scale),t.polygonOffset!==void 0&&(this.polygonOffset=t.polygonOffset),t.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=t.polygonOffsetFactor),t.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=t.polygonOffsetUnits),t.dithering!==void 0&&(this.dithering=t.dithering),t.alphaToCoverage!==void 0&&(this.alphaToCoverage=t.alphaToCoverage),t.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=t.premultipliedAlpha),t.forceSinglePass!==void 0&&(this.forceSinglePass=t.forceSinglePass),t.allowOverride!==void 0&&(this.allowOverride=t.allowOverride),t.visible!==void 0&&(this.visible=t.visible),t.toneMapped!==void 0&&(this.toneMapped=t.toneMapped),t.userData!==void 0&&(this.userData=t.userData),t.vertexColors!==void 0&&(typeof t.vertexColors=="number"?this.vertexColors=t.vertexColors>0:this.vertexColors=t.vertexColors),t.size!==void 0&&(this.size=t.size),t.sizeAttenuation!==void 0&&(this.sizeAttenuation=t.sizeAttenuation),t.map!==void 0&&(this.map=e[t.map]||null),t.matcap!==void 0&&(this.matcap=e[t.matcap]||null),t.alphaMap!==void 0&&(this.alphaMap=e[t.alphaMap]||null),t.bumpMap!==void 0&&(this.bumpMap=e[t.bumpMap]||null),t.bumpScale!==void 0&&(this.bumpScale=t.bumpScale),t.normalMap!==void 0&&(this.normalMap=e[t.normalMap]||null),t.normalMapType!==void 0&&(this.normalMapType=t.normalMapType),t.normalScale!==void 0){let n=t.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Ct().fromArray(n)}return t.displacementMap!==void 0&&(this.displacementMap=e[t.displacementMap]||null),t.displacementScale!==void 0&&(this.displacementScale=t.displacementScale),t.displacementBias!==void 0&&(this.displacementBias=t.displacementBias),t.roughnessMap!==void 0&&(this.roughnessMap=e[t.roughnessMap]||null),t.metalnessMap!==void 0&&(this.metalnessMap=e[t.metalnessMap]||null),t.emissiveMap!==void 0&&(this.emissiveMap=e[t.emissiveMap]||null),t.emissiveIntensity!==void 0&&(this.emissiveIntensity=t.emissiveIntensity),t.specularMap!==void 0&&(this.specularMap=e[t.specularMap]||null),t.specularIntensityMap!==void 0&&(this.specularIntensityMap=e[t.specularIntensityMap]||null),t.specularColorMap!==void 0&&(this.specularColorMap=e[t.specularColorMap]||null),t.envMap!==void 0&&(this.envMap=e[t.envMap]||null),t.envMapRotation!==void 0&&this.envMapRotation.fromArray(t.envMapRotation),t.envMapIntensity!==void 0&&(this.envMapIntensity=t.envMapIntensity),t.reflectivity!==void 0&&(this.reflectivity=t.reflectivity),t.refractionRatio!==void 0&&(this.refractionRatio=t.refractionRatio),t.lightMap!==void 0&&(this.lightMap=e[t.lightMap]||null),t.lightMapIntensity!==void 0&&(this.lightMapIntensity=t.lightMapIntensity),t.aoMap!==void 0&&(this.aoMap=e[t.aoMap]||null),t.aoMapIntensity!==void 0&&(this.aoMapIntensity=t.aoMapIntensity),t.gradientMap!==void 0&&(this.gradientMap=e[t.gradientMap]||null),t.clearcoatMap!==void 0&&(this.clearcoatMap=e[t.clearcoatMap]||null),t.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=e[t.clearcoatRoughnessMap]||null),t.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=e[t.clearcoatNormalMap]||null),t.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Ct().fromArray(t.clearcoatNormalScale)),t.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=e[t.diffuseRoughnessMap]||null),t.iridescenceMap!==void 0&&(this.iridescenceMap=e[t.iridescenceMap]||null),t.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=e[t.iridescenceThicknessMap]||null),t.transmissionMap!==void 0&&(this.transmissionMap=e[t.transmissionMap]||null),t.thicknessMap!==void 0&&(this.thicknessMap=e[t.thicknessMap]||null),t.anisotropyMap!==void 0&&(this.anisotropyMap=e[t.anisotropyMap]||null),t.sheenColorMap!==void 0&&(this.sheenColorMap=e[t.sheenColorMap]||null),t.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=e[t.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(t){this.name=t.name,this.blending=t.blending,this.side=t.side,this.vertexColors=t.vertexColors,this.opacity=t.opacity,this.transparent=t.transparent,this.blendSrc=t.blendSrc,this.blendDst=t.blendDst,this.blendEquation=t.blendEquation,this.blendSrcAlpha=t.blendSrcAlpha,this.blendDstAlpha=t.blendDstAlpha,this.blendEquationAlpha=t.blendEquationAlpha,this.blendColor.copy(t.blendColor),this.blendAlpha=t.blendAlpha,this.depthFunc=t.depthFunc,this.depthTest=t.depthTest,this.depthWrite=t.depthWrite,this.stencilWriteMask=t.stencilWriteMask,this.stencilFunc=t.stencilFunc,this.stencilRef=t.stencilRef,this.stencilFuncMask=t.stencilFuncMask,this.stencilFail=t.stencilFail,this.stencilZFail=t.stencilZFail,this.stencilZPass=t.stencilZPass,this.stencilWrite=t.stencilWrite;let e=t.clippingPlanes,n=null;if(e!==null){let a=e.length;n=new Array(a);for(let s=0;s!==a;++s)n[s]=e[s].clone()}return this.clippingPlanes=n,this.clipIntersection=t.clipIntersection,this.clipShadows=t.clipShadows,this.shadowSide=t.shadowSide,this.colorWrite=t.colorWrite,this.precision=t.precision,this.polygonOffset=t.polygonOffset,this.polygonOffsetFactor=t.polygonOffsetFactor,this.polygonOffsetUnits=t.polygonOffsetUnits,this.dithering=t.dithering,this.alphaTest=t.alphaTest,this.alphaHash=t.alphaHash,this.alphaToCoverage=t.alphaToCoverage,this.premultipliedAlpha=t.premultipliedAlpha,this.forceSinglePass=t.forceSinglePass,this.allowOverride=t.allowOverride,this.visible=t.visible,this.toneMapped=t.toneMapped,this.userData=JSON.parse(JSON.stringify(t.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(t){t===!0&&this.version++}},wi=new F,Ch=new F,Eo=new F,To=new F,Kn=class{constructor(t=new F,e=new F(0,0,-1)){this.origin=t,this.direction=e}set(t,e){return this.origin.copy(t),this.direction.copy(e),this}copy(t){return this.origin.copy(t.origin),this.direction.copy(t.direction),this}at(t,e){return e.copy(this.origin).addScaledVector(this.direction,t)}lookAt(t){return this.direction.copy(t).sub(this.origin).normalize(),this}recast(t){return this.origin.copy(this.at(t,wi)),this}closestPointToPoint(t,e){e.subVectors(t,this.origin);let n=e.dot(this.direction);return n<0?e.copy(this.origin):e.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(t){return Math.sqrt(this.distanceSqToPoint(t))}distanceSqToPoint(t){let e=wi.subVectors(t,this.origin).dot(this.direction);return e<0?this.origin.distanceToSquared(t):(wi.copy(this.origin).addScaledVector(this.direction,e),wi.distanceToSquared(t))}distanceSqToSegment(t,e,n,a){Ch.copy(t).add(e).multiplyScalar(.5),Eo.copy(e).sub(t).normalize(),To.copy(this.origin).sub(Ch);let s=t.distanceTo(e)*.5,r=-this.direction.dot(Eo),o=To.dot(this.direction),c=-To.dot(Eo),l=To.lengthSq(),h=Math.abs(1-r*r),u,d,f,m;if(h>0)if(u=r*c-o,d=r*o-c,m=s*h,u>=0)if(d>=-m)if(d<=m){let y=1/h;u*=y,d*=y,f=u*(u+r*d+2*o)+d*(r*u+d+2*c)+l}else d=s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;else d=-s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;else d<=-m?(u=Math.max(0,-(-r*s+o)),d=u>0?-s:Math.min(Math.max(-s,-c),s),f=-u*u+d*(d+2*c)+l):d<=m?(u=0,d=Math.min(Math.max(-s,-c),s),f=d*(d+2*c)+l):(u=Math.max(0,-(r*s+o)),d=u>0?s:Math.min(Math.max(-s,-c),s),f=-u*u+d*(d+2*c)+l);else d=r>0?-s:s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;return n&&n.copy(this.origin).addScaledVector(this.direction,u),a&&a.copy(Ch).addScaledVector(Eo,d),f}intersectSphere(t,e){if(t.radius<0)return null;wi.subVectors(t.center,this.origin);let n=wi.dot(this.direction),a=wi.dot(wi)-n*n,s=t.radius*t.radius;if(a>s)return null;let r=Math.sqrt(s-a),o=n-r,c=n+r;return c<0?null:o<0?this.at(c,e):this.at(o,e)}intersectsSphere(t){return t.radius<0?!1:this.distanceSqToPoint(t.center)<=t.radius*t.radius}distanceToPlane(t){let e=t.normal.dot(this.direction);if(e===0)return t.distanceToPoint(this.origin)===0?0:null;let n=-(this.origin.dot(t.normal)+t.constant)/e;return n>=0?n:null}intersectPlane(t,e){let n=this.distanceToPlane(t);return n===null?null:this.at(n,e)}intersectsPlane(t){let e=t.distanceToPoint(this.origin);return e===0||t.normal.dot(this.direction)*e<0}intersectBox(t,e){let n,a,s,r,o,c,l=1/this.direction.x,h=1/this.direction.y,u=1/this.direction.z,d=this.origin;return l>=0?(n=(t.min.x-d.x)*l,a=(t.max.x-d.x)*l):(n=(t.max.x-d.x)*l,a=(t.min.x-d.x)*l),h>=0?(s=(t.min.y-d.y)*h,r=(t.max.y-d.y)*h):(s=(t.max.y-d.y)*h,r=(t.min.y-d.y)*h),n>r||s>a||((s>n||isNaN(n))&&(n=s),(r<a||isNaN(a))&&(a=r),u>=0?(o=(t.min.z-d.z)*u,c=(t.max.z-d.z)*u):(o=(t.max.z-d.z)*u,c=(t.min.z-d.z)*u),n>c||o>a)||((o>n||n!==n)&&(n=o),(c<a||a!==a)&&(a=c),a<0)?null:this.at(n>=0?n:a,e)}intersectsBox(t){return this.intersectBox(t,wi)!==null}intersectTriangle(t,e,n,a,s){let r=this.origin,o=this.direction,c=o.x,l=o.y,h=o.z,u=t.x-r.x,d=t.y-r.y,f=t.z-r.z,m=e.x-r.x,y=e.y-r.y,g=e.z-r.z,b=n.x-r.x,v=n.y-r.y,w=n.z-r.z,p=Math.abs(c),_=Math.abs(l),M=Math.abs(h),x,S,E,A,R,C,L,N,U,z,B,K;if(p>=_&&p>=M?(E=c,C=u,U=m,K=b,c>=0?(x=l,S=h,A=d,R=f,L=y,N=g,z=v,B=w):(x=h,S=l,A=f,R=d,L=g,N=y,z=w,B=v)):_>=M?(E=l,C=d,U=y,K=v,l>=0?(x=h,S=c,A=f,R=u,L=g,N=m,z=w,B=b):(x=c,S=h,A=u,R=f,L=m,N=g,z=b,B=w)):(E=h,C=f,U=g,K=w,h>=0?(x=c,S=l,A=u,R=d,L=m,N=y,z=b,B=v):(x=l,S=c,A=d,R=u,L=y,N=m,z=v,B=b)),E===0)return null;let W=x/E,Y=S/E,tt=1/E,gt=A-W*C,It=R-Y*C,X=L-W*U,it=N-Y*U,_t=z-W*K,Et=B-Y*K,pt=_t*it-Et*X,Ut=gt*Et-It*_t,ye=X*It-it*gt;if(a){if(pt<0||Ut<0||ye<0)return null}else if((pt<0||Ut<0||ye<0)&&(pt>0||Ut>0||ye>0))return null;let Nt=pt+Ut+ye;if(Nt===0)return null;let Jt=tt*(pt*C+Ut*U+ye*K);return(Nt>0?Jt<0:Jt>0)?null:this.at(Jt/Nt,s)}applyMatrix4(t){return this.origin.applyMatrix4(t),this.direction.transformDirection(t),this}equals(t){return t.origin.equals(this.origin)&&t.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},is=class extends ri{constructor(t){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new kt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ri,this.combine=Ic,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.fog=t.fog,this}},Pf=new Zt,ma=new Kn,Io=new ze,Lf=new F,Ro=new F,Co=new F,No=new F,Nh=new F,Po=new F,Df=new F,Lo=new F,tn=class extends Re{constructor(t=new Ae,e=new is){super(),this.isMesh=!0,this.type="Mesh",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}getVertexPosition(t,e){let n=this.geometry,a=n.attributes.position,s=n.morphAttributes.position,r=n.morphTargetsRelative;e.fromBufferAttribute(a,t);let o=this.morphTargetInfluences;if(s&&o){Po.set(0,0,0);for(let c=0,l=s.length;c<l;c++){let h=o[c],u=s[c];h!==0&&(Nh.fromBufferAttribute(u,t),r?Po.addScaledVector(Nh,h):Po.addScaledVector(Nh.sub(e),h))}e.add(Po)}return e}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.material,s=this.matrixWorld;a!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),Io.copy(n.boundingSphere),Io.applyMatrix4(s),ma.copy(t.ray).recast(t.near),!(Io.containsPoint(ma.origin)===!1&&(ma.intersectSphere(Io,Lf)===null||ma.origin.distanceToSquared(Lf)>(t.far-t.near)**2))&&(Pf.copy(s).invert(),ma.copy(t.ray).applyMatrix4(Pf),!(n.boundingBox!==null&&ma.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(t,e,ma)))}_computeIntersections(t,e,n){let a,s=this.geometry,r=this.material,o=s.index,c=s.attributes.position,l=s.attributes.uv,h=s.attributes.uv1,u=s.attributes.normal,d=s.groups,f=s.drawRange;if(o!==null)if(Array.isArray(r))for(let m=0,y=d.length;m<y;m++){let g=d[m],b=r[g.materialIndex],v=Math.max(g.start,f.start),w=Math.min(o.count,Math.min(g.start+g.count,f.start+f.count));for(let p=v,_=w;p<_;p+=3){let M=o.getX(p),x=o.getX(p+1),S=o.getX(p+2);a=Do(this,b,t,n,l,h,u,M,x,S),a&&(a.faceIndex=Math.floor(p/3),a.face.materialIndex=g.materialIndex,e.push(a))}}else{let m=Math.max(0,f.start),y=Math.min(o.count,f.start+f.count);for(let g=m,b=y;g<b;g+=3){let v=o.getX(g),w=o.getX(g+1),p=o.getX(g+2);a=Do(this,r,t,n,l,h,u,v,w,p),a&&(a.faceIndex=Math.floor(g/3),e.push(a))}}else if(c!==void 0)if(Array.isArray(r))for(let m=0,y=d.length;m<y;m++){let g=d[m],b=r[g.materialIndex],v=Math.max(g.start,f.start),w=Math.min(c.count,Math.min(g.start+g.count,f.start+f.count));for(let p=v,_=w;p<_;p+=3){let M=p,x=p+1,S=p+2;a=Do(this,b,t,n,l,h,u,M,x,S),a&&(a.faceIndex=Math.floor(p/3),a.face.materialIndex=g.materialIndex,e.push(a))}}else{let m=Math.max(0,f.start),y=Math.min(c.count,f.start+f.count);for(let g=m,b=y;g<b;g+=3){let v=g,w=g+1,p=g+2;a=Do(this,r,t,n,l,h,u,v,w,p),a&&(a.faceIndex=Math.floor(g/3),e.push(a))}}}};Ti=class extends vn{constructor(t=null,e=1,n=1,a,s,r,o,c,l=we,h=we,u,d){super(null,r,o,c,l,h,a,s,u,d),this.isDataTexture=!0,this.image={data:t,width:e,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}},ga=new ze,Wx=new Ct(.5,.5),Uo=new F,Ci=class{constructor(t=new hn,e=new hn,n=new hn,a=new hn,s=new hn,r=new hn){this.planes=[t,e,n,a,s,r]}set(t,e,n,a,s,r){let o=this.planes;return o[0].copy(t),o[1].copy(e),o[2].copy(n),o[3].copy(a),o[4].copy(s),o[5].copy(r),this}copy(t){let e=this.planes;for(let n=0;n<6;n++)e[n].copy(t.planes[n]);return this}setFromProjectionMatrix(t,e=Fn,n=!1){let a=this.planes,s=t.elements,r=s[0],o=s[1],c=s[2],l=s[3],h=s[4],u=s[5],d=s[6],f=s[7],m=s[8],y=s[9],g=s[10],b=s[11],v=s[12],w=s[13],p=s[14],_=s[15];if(a[0].setComponents(l-r,f-h,b-m,_-v).normalize(),a[1].setComponents(l+r,f+h,b+m,_+v).normalize(),a[2].setComponents(l+o,f+u,b+y,_+w).normalize(),a[3].setComponents(l-o,f-u,b-y,_-w).normalize(),n)a[4].setComponents(c,d,g,p).normalize(),a[5].setComponents(l-c,f-d,b-g,_-p).normalize();else if(a[4].setComponents(l-c,f-d,b-g,_-p).normalize(),e===Fn)a[5].setComponents(l+c,f+d,b+g,_+p).normalize();else if(e===Za)a[5].setComponents(c,d,g,p).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+e);return this}intersectsObject(t){if(t.boundingSphere!==void 0)t.boundingSphere===null&&t.computeBoundingSphere(),ga.copy(t.boundingSphere).applyMatrix4(t.matrixWorld);else{let e=t.geometry;e.boundingSphere===null&&e.computeBoundingSphere(),ga.copy(e.boundingSphere).applyMatrix4(t.matrixWorld)}return this.intersectsSphere(ga)}intersectsSprite(t){ga.center.set(0,0,0);let e=Wx.distanceTo(t.center);return ga.radius=.7071067811865476+e,ga.applyMatrix4(t.matrixWorld),this.intersectsSphere(ga)}intersectsSphere(t){let e=this.planes,n=t.center,a=-t.radius;for(let s=0;s<6;s++)if(e[s].distanceToPoint(n)<a)return!1;return!0}intersectsBox(t){let e=this.planes;for(let n=0;n<6;n++){let a=e[n];if(Uo.x=a.normal.x>0?t.max.x:t.min.x,Uo.y=a.normal.y>0?t.max.y:t.min.y,Uo.z=a.normal.z>0?t.max.z:t.min.z,a.distanceToPoint(Uo)<0)return!1}return!0}containsPoint(t){let e=this.planes;for(let n=0;n<6;n++)if(e[n].distanceToPoint(t)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},Uf=new Zt,lr=class i{constructor(){this.coordinateSystem=Fn,this._frustums=[],this._count=0}setFromArrayCamera(t){let e=t.cameras,n=this._frustums;for(let a=0;a<e.length;a++){let s=e[a];Uf.multiplyMatrices(s.projectionMatrix,s.matrixWorldInverse),n[a]===void 0&&(n[a]=new Ci),n[a].setFromProjectionMatrix(Uf,s.coordinateSystem,s.reversedDepth)}return this._count=e.length,this}getFrustum(t){return this._frustums[t]}intersectsObject(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsObject(t))return!0;return!1}intersectsSprite(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSprite(t))return!0;return!1}intersectsSphere(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSphere(t))return!0;return!1}intersectsBox(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsBox(t))return!0;return!1}containsPoint(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].containsPoint(t))return!0;return!1}copy(t){this.coordinateSystem=t.coordinateSystem;let e=this._frustums,n=t._frustums;for(let a=0;a<t._count;a++)e[a]===void 0&&(e[a]=new Ci),e[a].copy(n[a]);return this._count=t._count,this}clone(){return new i().copy(this)}};Hh=class{constructor(){this.index=0,this.pool=[],this.list=[]}push(t,e,n,a){let s=this.pool,r=this.list;this.index>=s.length&&s.push({start:-1,count:-1,z:-1,index:-1});let o=s[this.index];r.push(o),this.index++,o.start=t,o.count=e,o.z=n,o.index=a}reset(){this.list.length=0,this.index=0}},_n=new Zt,qx=new kt(1,1,1),Yx=new Ci,Jx=new lr,Oo=new Ie,ba=new ze,Lh=new F,Of=new F,Ff=new F,Kx=new F,Dh=new Hh,Qe=new tn,Fo=[];hr=class extends tn{constructor(t,e,n=e*2,a){super(new Ae,a),this.isBatchedMesh=!0,this.perObjectFrustumCulled=!0,this.sortObjects=!0,this.boundingBox=null,this.boundingSphere=null,this.customSort=null,this._instanceInfo=[],this._geometryInfo=[],this._availableInstanceIds=[],this._availableGeometryIds=[],this._nextIndexStart=0,this._nextVertexStart=0,this._geometryCount=0,this._visibilityChanged=!0,this._geometryInitialized=!1,this._maxInstanceCount=t,this._maxVertexCount=e,this._maxIndexCount=n,this._multiDrawCounts=new Int32Array(t),this._multiDrawStarts=new Int32Array(t),this._multiDrawCount=0,this._multiDrawBytesPerElement=1,this._mergedDrawCounts=new Int32Array(t),this._mergedDrawStarts=new Int32Array(t),this._mergedDrawInstanceCounts=new Int32Array(t),this._mergedDrawCount=0,this._matricesTexture=null,this._indirectTexture=null,this._colorsTexture=null,this._previousMatricesTexture=null,this._initMatricesTexture(),this._initIndirectTexture()}get maxInstanceCount(){return this._maxInstanceCount}get instanceCount(){return this._instanceInfo.length-this._availableInstanceIds.length}get unusedVertexCount(){return this._maxVertexCount-this._nextVertexStart}get unusedIndexCount(){return this._maxIndexCount-this._nextIndexStart}_initMatricesTexture(){let t=Math.sqrt(this._maxInstanceCount*4);t=Math.ceil(t/4)*4,t=Math.max(t,4);let e=new Float32Array(t*t*4),n=new Ti(e,t,t,mn,pn);this._matricesTexture=n}_initIndirectTexture(){let t=Math.sqrt(this._maxInstanceCount);t=Math.ceil(t);let e=new Uint32Array(t*t),n=new Ti(e,t,t,Aa,Mn);this._indirectTexture=n}_initColorsTexture(){let t=Math.sqrt(this._maxInstanceCount);t=Math.ceil(t);let e=new Float32Array(t*t*4).fill(1),n=new Ti(e,t,t,mn,pn);n.colorSpace=Gt.workingColorSpace,this._colorsTexture=n}_initializeGeometry(t){let e=this.geometry,n=this._maxVertexCount,a=this._maxIndexCount;if(this._geometryInitialized===!1){for(let s in t.attributes){let r=t.getAttribute(s),{array:o,itemSize:c,normalized:l}=r,h=new o.constructor(n*c),u=new un(h,c,l);e.setAttribute(s,u)}if(t.getIndex()!==null){let s=n>65535?new Uint32Array(a):new Uint16Array(a);e.setIndex(new un(s,1))}this._geometryInitialized=!0}}_validateGeometry(t){let e=this.geometry;if(!!t.getIndex()!=!!e.getIndex())throw new Error('THREE.BatchedMesh: All geometries must consistently have "index".');for(let n in e.attributes){if(!t.hasAttribute(n))throw new Error(`THREE.BatchedMesh: Added geometry missing "${n}". All geometries must have consistent attributes.`);let a=t.getAttribute(n),s=e.getAttribute(n);if(a.itemSize!==s.itemSize||a.normalized!==s.normalized)throw new Error(`THREE.BatchedMesh: Added geometry attribute "${n}" has an inconsistent itemSize or normalized value.`)}}validateInstanceId(t){let e=this._instanceInfo;if(t<0||t>=e.length||e[t].active===!1)throw new Error(`THREE.BatchedMesh: Invalid instanceId ${t}. Instance is either out of range or has been deleted.`)}validateGeometryId(t){let e=this._geometryInfo;if(t<0||t>=e.length||e[t].active===!1)throw new Error(`THREE.BatchedMesh: Invalid geometryId ${t}. Geometry is either out of range or has been deleted.`)}setCustomSort(t){return this.customSort=t,this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ie);let t=this.boundingBox,e=this._instanceInfo;t.makeEmpty();for(let n=0,a=e.length;n<a;n++){if(e[n].active===!1)continue;let s=e[n].geometryIndex;this.getMatrixAt(n,_n),this.getBoundingBoxAt(s,Oo).applyMatrix4(_n),t.union(Oo)}}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new ze);let t=this.boundingSphere,e=this._instanceInfo;t.makeEmpty();for(let n=0,a=e.length;n<a;n++){if(e[n].active===!1)continue;let s=e[n].geometryIndex;this.getMatrixAt(n,_n),this.getBoundingSphereAt(s,ba).applyMatrix4(_n),t.union(ba)}}addInstance(t){if(this._instanceInfo.length>=this.maxInstanceCount&&this._availableInstanceIds.length===0)throw new Error("THREE.BatchedMesh: Maximum item count reached.");let n={visible:!0,active:!0,geometryIndex:t},a=null;this._availableInstanceIds.length>0?(this._availableInstanceIds.sort(Ph),a=this._availableInstanceIds.shift(),this._instanceInfo[a]=n):(a=this._instanceInfo.length,this._instanceInfo.push(n));let s=this._matricesTexture;_n.identity().toArray(s.image.data,a*16),s.needsUpdate=!0;let r=this._colorsTexture;return r&&(qx.toArray(r.image.data,a*4),r.needsUpdate=!0),this._visibilityChanged=!0,a}addGeometry(t,e=-1,n=-1){this._initializeGeometry(t),this._validateGeometry(t);let a={vertexStart:-1,vertexCount:-1,reservedVertexCount:-1,indexStart:-1,indexCount:-1,reservedIndexCount:-1,start:-1,count:-1,boundingBox:null,boundingSphere:null,active:!0},s=this._geometryInfo;a.vertexStart=this._nextVertexStart,a.reservedVertexCount=e===-1?t.getAttribute("position").count:e;let r=t.getIndex();if(r!==null&&(a.indexStart=this._nextIndexStart,a.reservedIndexCount=n===-1?r.count:n),a.indexStart!==-1&&a.indexStart+a.reservedIndexCount>this._maxIndexCount||a.vertexStart+a.reservedVertexCount>this._maxVertexCount)throw new Error("THREE.BatchedMesh: Reserved space request exceeds the maximum buffer size.");let c;return this._availableGeometryIds.length>0?(this._availableGeometryIds.sort(Ph),c=this._availableGeometryIds.shift(),s[c]=a):(c=this._geometryCount,this._geometryCount++,s.push(a)),this.setGeometryAt(c,t),this._nextIndexStart=a.indexStart+a.reservedIndexCount,this._nextVertexStart=a.vertexStart+a.reservedVertexCount,c}setGeometryAt(t,e){if(t>=this._geometryCount)throw new Error("THREE.BatchedMesh: Maximum geometry count reached.");this._validateGeometry(e);let n=this.geometry,a=n.getIndex()!==null,s=n.getIndex(),r=e.getIndex(),o=this._geometryInfo[t];if(a&&r.count>o.reservedIndexCount||e.attributes.position.count>o.reservedVertexCount)throw new Error("THREE.BatchedMesh: Reserved space not large enough for provided geometry.");let c=o.vertexStart,l=o.reservedVertexCount;o.vertexCount=e.getAttribute("position").count;for(let h in n.attributes){let u=e.getAttribute(h),d=n.getAttribute(h);Zx(u,d,c);let f=u.itemSize;for(let m=u.count,y=l;m<y;m++){let g=c+m;for(let b=0;b<f;b++)d.setComponent(g,b,0)}d.needsUpdate=!0,d.addUpdateRange(c*f,l*f)}if(a){let h=o.indexStart,u=o.reservedIndexCount;o.indexCount=e.getIndex().count;for(let d=0;d<r.count;d++)s.setX(h+d,c+r.getX(d));for(let d=r.count,f=u;d<f;d++)s.setX(h+d,c);s.needsUpdate=!0,s.addUpdateRange(h,o.reservedIndexCount)}return o.start=a?o.indexStart:o.vertexStart,o.count=a?o.indexCount:o.vertexCount,o.boundingBox=null,e.boundingBox!==null&&(o.boundingBox=e.boundingBox.clone()),o.boundingSphere=null,e.boundingSphere!==null&&(o.boundingSphere=e.boundingSphere.clone()),this._visibilityChanged=!0,t}deleteGeometry(t){let e=this._geometryInfo;if(t>=e.length||e[t].active===!1)return this;let n=this._instanceInfo;for(let a=0,s=n.length;a<s;a++)n[a].active&&n[a].geometryIndex===t&&this.deleteInstance(a);return e[t].active=!1,this._availableGeometryIds.push(t),this._visibilityChanged=!0,this}deleteInstance(t){return this.validateInstanceId(t),this._instanceInfo[t].active=!1,this._availableInstanceIds.push(t),this._visibilityChanged=!0,this}optimize(){let t=0,e=0,n=this._geometryInfo,a=n.map((r,o)=>o).sort((r,o)=>n[r].vertexStart-n[o].vertexStart),s=this.geometry;for(let r=0,o=n.length;r<o;r++){let c=a[r],l=n[c];if(l.active!==!1){if(s.index!==null){if(l.indexStart!==e){let{indexStart:h,vertexStart:u,reservedIndexCount:d}=l,f=s.index,m=f.array,y=t-u;for(let g=h;g<h+d;g++)m[g]=m[g]+y;f.array.copyWithin(e,h,h+d),f.addUpdateRange(e,d),f.needsUpdate=!0,l.indexStart=e}e+=l.reservedIndexCount}if(l.vertexStart!==t){let{vertexStart:h,reservedVertexCount:u}=l,d=s.attributes;for(let f in d){let m=d[f],{array:y,itemSize:g}=m;y.copyWithin(t*g,h*g,(h+u)*g),m.addUpdateRange(t*g,u*g),m.needsUpdate=!0}l.vertexStart=t}t+=l.reservedVertexCount,l.start=s.index?l.indexStart:l.vertexStart}}return this._nextIndexStart=e,this._nextVertexStart=t,this._visibilityChanged=!0,this}getBoundingBoxAt(t,e){if(t>=this._geometryCount)return null;let n=this.geometry,a=this._geometryInfo[t];if(a.boundingBox===null){let s=new Ie,r=n.index,o=n.attributes.position;for(let c=a.start,l=a.start+a.count;c<l;c++){let h=c;r&&(h=r.getX(h)),s.expandByPoint(Lh.fromBufferAttribute(o,h))}a.boundingBox=s}return e.copy(a.boundingBox),e}getBoundingSphereAt(t,e){if(t>=this._geometryCount)return null;let n=this.geometry,a=this._geometryInfo[t];if(a.boundingSphere===null){let s=new ze;this.getBoundingBoxAt(t,Oo),Oo.getCenter(s.center);let r=n.index,o=n.attributes.position,c=0;for(let l=a.start,h=a.start+a.count;l<h;l++){let u=l;r&&(u=r.getX(u)),Lh.fromBufferAttribute(o,u),c=Math.max(c,s.center.distanceToSquared(Lh))}s.radius=Math.sqrt(c),a.boundingSphere=s}return e.copy(a.boundingSphere),e}setMatrixAt(t,e){this.validateInstanceId(t);let n=this._matricesTexture,a=this._matricesTexture.image.data;return e.toArray(a,t*16),n.needsUpdate=!0,this}getMatrixAt(t,e){return this.validateInstanceId(t),e.fromArray(this._matricesTexture.image.data,t*16)}setColorAt(t,e){return this.validateInstanceId(t),this._colorsTexture===null&&this._initColorsTexture(),e.toArray(this._colorsTexture.image.data,t*4),this._colorsTexture.needsUpdate=!0,this}getColorAt(t,e){return this.validateInstanceId(t),this._colorsTexture===null?e.isVector4?e.set(1,1,1,1):e.setRGB(1,1,1):e.fromArray(this._colorsTexture.image.data,t*4)}setVisibleAt(t,e){return this.validateInstanceId(t),this._instanceInfo[t].visible===e?this:(this._instanceInfo[t].visible=e,this._visibilityChanged=!0,this)}getVisibleAt(t){return this.validateInstanceId(t),this._instanceInfo[t].visible}setGeometryIdAt(t,e){return this.validateInstanceId(t),this.validateGeometryId(e),this._instanceInfo[t].geometryIndex=e,this._visibilityChanged=!0,this}getGeometryIdAt(t){return this.validateInstanceId(t),this._instanceInfo[t].geometryIndex}getGeometryRangeAt(t,e={}){this.validateGeometryId(t);let n=this._geometryInfo[t];return e.vertexStart=n.vertexStart,e.vertexCount=n.vertexCount,e.reservedVertexCount=n.reservedVertexCount,e.indexStart=n.indexStart,e.indexCount=n.indexCount,e.reservedIndexCount=n.reservedIndexCount,e.start=n.start,e.count=n.count,e}setInstanceCount(t){let e=this._availableInstanceIds,n=this._instanceInfo;for(e.sort(Ph);e[e.length-1]===n.length-1;)n.pop(),e.pop();if(t<n.length)throw new Error(`THREE.BatchedMesh: Instance ids outside the range ${t} are being used. Cannot shrink instance count.`);let a=new Int32Array(t),s=new Int32Array(t);ni(this._multiDrawCounts,a),ni(this._multiDrawStarts,s),this._multiDrawCounts=a,this._multiDrawStarts=s;let r=new Int32Array(t),o=new Int32Array(t),c=new Int32Array(t);ni(this._mergedDrawCounts,r),ni(this._mergedDrawStarts,o),ni(this._mergedDrawInstanceCounts,c),this._mergedDrawCounts=r,this._mergedDrawStarts=o,this._mergedDrawInstanceCounts=c,this._maxInstanceCount=t;let l=this._indirectTexture,h=this._matricesTexture,u=this._colorsTexture;l.dispose(),this._initIndirectTexture(),ni(l.image.data,this._indirectTexture.image.data),h.dispose(),this._initMatricesTexture(),ni(h.image.data,this._matricesTexture.image.data),u&&(u.dispose(),this._initColorsTexture(),ni(u.image.data,this._colorsTexture.image.data)),this._previousMatricesTexture!==null&&(this._previousMatricesTexture.dispose(),this._previousMatricesTexture=null)}setGeometrySize(t,e){let n=[...this._geometryInfo].filter(o=>o.active);if(Math.max(...n.map(o=>o.vertexStart+o.reservedVertexCount))>t)throw new Error(`THREE.BatchedMesh: Geometry vertex values are being used outside the range ${t}. Cannot shrink further.`);if(this.geometry.index&&Math.max(...n.map(c=>c.indexStart+c.reservedIndexCount))>e)throw new Error(`THREE.BatchedMesh: Geometry index values are being used outside the range ${e}. Cannot shrink further.`);let s=this.geometry;s.dispose(),this._maxVertexCount=t,this._maxIndexCount=e,this._geometryInitialized&&(this._geometryInitialized=!1,this.geometry=new Ae,this._initializeGeometry(s));let r=this.geometry;s.index&&ni(s.index.array,r.index.array);for(let o in s.attributes)ni(s.attributes[o].array,r.attributes[o].array);this._visibilityChanged=!0}raycast(t,e){let n=this._instanceInfo,a=this._geometryInfo,s=this.matrixWorld,r=this.geometry;Qe.material=this.material,Qe.geometry.index=r.index,Qe.geometry.attributes=r.attributes,Qe.geometry.boundingBox===null&&(Qe.geometry.boundingBox=new Ie),Qe.geometry.boundingSphere===null&&(Qe.geometry.boundingSphere=new ze);for(let o=0,c=n.length;o<c;o++){if(!n[o].visible||!n[o].active)continue;let l=n[o].geometryIndex,h=a[l];Qe.geometry.setDrawRange(h.start,h.count),this.getMatrixAt(o,Qe.matrixWorld).premultiply(s),this.getBoundingBoxAt(l,Qe.geometry.boundingBox),this.getBoundingSphereAt(l,Qe.geometry.boundingSphere),Qe.raycast(t,Fo);for(let u=0,d=Fo.length;u<d;u++){let f=Fo[u];f.object=this,f.batchId=o,e.push(f)}Fo.length=0}Qe.material=null,Qe.geometry.index=null,Qe.geometry.attributes={},Qe.geometry.setDrawRange(0,1/0)}copy(t){return super.copy(t),this.geometry=t.geometry.clone(),this.perObjectFrustumCulled=t.perObjectFrustumCulled,this.sortObjects=t.sortObjects,this.boundingBox=t.boundingBox!==null?t.boundingBox.clone():null,this.boundingSphere=t.boundingSphere!==null?t.boundingSphere.clone():null,this._geometryInfo=t._geometryInfo.map(e=>({...e,boundingBox:e.boundingBox!==null?e.boundingBox.clone():null,boundingSphere:e.boundingSphere!==null?e.boundingSphere.clone():null})),this._instanceInfo=t._instanceInfo.map(e=>({...e})),this._availableInstanceIds=t._availableInstanceIds.slice(),this._availableGeometryIds=t._availableGeometryIds.slice(),this._nextIndexStart=t._nextIndexStart,this._nextVertexStart=t._nextVertexStart,this._geometryCount=t._geometryCount,this._maxInstanceCount=t._maxInstanceCount,this._maxVertexCount=t._maxVertexCount,this._maxIndexCount=t._maxIndexCount,this._geometryInitialized=t._geometryInitialized,this._multiDrawCounts=t._multiDrawCounts.slice(),this._multiDrawStarts=t._multiDrawStarts.slice(),this._multiDrawBytesPerElement=t._multiDrawBytesPerElement,this._mergedDrawCounts=t._mergedDrawCounts.slice(),this._mergedDrawStarts=t._mergedDrawStarts.slice(),this._mergedDrawInstanceCounts=t._mergedDrawInstanceCounts.slice(),this._indirectTexture=t._indirectTexture.clone(),this._indirectTexture.image.data=this._indirectTexture.image.data.slice(),this._matricesTexture=t._matricesTexture.clone(),this._matricesTexture.image.data=this._matricesTexture.image.data.slice(),t._colorsTexture!==null?(this._colorsTexture=t._colorsTexture.clone(),this._colorsTexture.image.data=this._colorsTexture.image.data.slice()):this._colorsTexture=null,this}dispose(){super.dispose(),this.geometry.dispose(),this._matricesTexture.dispose(),this._matricesTexture=null,this._indirectTexture.dispose(),this._indirectTexture=null,this._colorsTexture!==null&&(this._colorsTexture.dispose(),this._colorsTexture=null),this._previousMatricesTexture!==null&&(this._previousMatricesTexture.dispose(),this._previousMatricesTexture=null)}_updateDrawParameters(t,e,n,a="multiDraw"){if(!this._visibilityChanged&&!this.perObjectFrustumCulled&&!this.sortObjects)return;let s=e.getIndex(),r=s===null?1:s.array.BYTES_PER_ELEMENT,o=1;n.wireframe&&(o=2,r=e.attributes.position.count>65535?4:2);let c=this._instanceInfo,l=this._multiDrawStarts,h=this._multiDrawCounts,u=this._mergedDrawStarts,d=this._mergedDrawCounts,f=this._mergedDrawInstanceCounts,m=this._geometryInfo,y=this.perObjectFrustumCulled,g=this._indirectTexture,b=g.image.data,v=t.isArrayCamera?Jx:Yx;y&&(t.isArrayCamera?v.setFromArrayCamera(t):(_n.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse).multiply(this.matrixWorld),v.setFromProjectionMatrix(_n,t.coordinateSystem,t.reversedDepth)));let w=0,p=0;if(this.sortObjects){_n.copy(this.matrixWorld).invert(),Of.setFromMatrixPosition(t.matrixWorld).applyMatrix4(_n),Ff.set(0,0,-1).transformDirection(t.matrixWorld).transformDirection(_n);for(let x=0,S=c.length;x<S;x++)if(c[x].visible&&c[x].active){let E=c[x].geometryIndex;this.getMatrixAt(x,_n),this.getBoundingSphereAt(E,ba).applyMatrix4(_n);let A=!1;if(y&&(A=!v.intersectsSphere(ba)),!A){let R=m[E],C=Kx.subVectors(ba.center,Of).dot(Ff);Dh.push(R.start,R.count,C,x)}}let _=Dh.list,M=this.customSort;M===null?_.sort(n.transparent?Xx:jx):M.call(this,_,t);for(let x=0,S=_.length;x<S;x++){let E=_[x],A=E.start*r*o,R=E.count*o;a==="merged"?p>0&&u[p-1]===A&&d[p-1]===R?f[p-1]++:(u[p]=A,d[p]=R,f[p]=1,p++):(l[w]=A,h[w]=R),b[w]=E.index,w++}Dh.reset()}else for(let _=0,M=c.length;_<M;_++)if(c[_].visible&&c[_].active){let x=c[_].geometryIndex,S=!1;if(y&&(this.getMatrixAt(_,_n),this.getBoundingSphereAt(x,ba).applyMatrix4(_n),S=!v.intersectsSphere(ba)),!S){let E=m[x],A=E.start*r*o,R=E.count*o;a==="merged"?p>0&&u[p-1]===A&&d[p-1]===R?f[p-1]++:(u[p]=A,d[p]=R,f[p]=1,p++):(l[w]=A,h[w]=R),b[w]=_,w++}}g.needsUpdate=!0,this._multiDrawCount=w,this._mergedDrawCount=p,this._multiDrawBytesPerElement=r,this._visibilityChanged=!1}onBeforeRender(t,e,n,a,s){t.isWebGPURenderer===!0?(this._visibilityChanged||this.perObjectFrustumCulled||this.sortObjects)&&(this._indirectTexture.needsUpdate=!0):this._updateDrawParameters(n,a,s)}onBeforeShadow(t,e,n,a,s,r){t.isWebGPURenderer!==!0&&this._updateDrawParameters(a,s,r)}},xa=class extends ri{constructor(t){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new kt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.linewidth=t.linewidth,this.linecap=t.linecap,this.linejoin=t.linejoin,this.fog=t.fog,this}},cc=new F,lc=new F,Bf=new Zt,Ks=new Kn,Bo=new ze,Uh=new F,kf=new F,ya=class extends Re{constructor(t=new Ae,e=new xa){super(),this.isLine=!0,this.type="Line",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}computeLineDistances(){let t=this.geometry;if(t.index===null){let e=t.attributes.position,n=[0];for(let a=1,s=e.count;a<s;a++)cc.fromBufferAttribute(e,a-1),lc.fromBufferAttribute(e,a),n[a]=n[a-1],n[a]+=cc.distanceTo(lc);t.setAttribute("lineDistance",new re(n,1))}else Rt("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.matrixWorld,s=t.params.Line.threshold,r=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),Bo.copy(n.boundingSphere),Bo.applyMatrix4(a),Bo.radius+=s,t.ray.intersectsSphere(Bo)===!1)return;Bf.copy(a).invert(),Ks.copy(t.ray).applyMatrix4(Bf);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=this.isLineSegments?2:1,h=n.index,d=n.attributes.position;if(h!==null){let f=Math.max(0,r.start),m=Math.min(h.count,r.start+r.count);for(let y=f,g=m-1;y<g;y+=l){let b=h.getX(y),v=h.getX(y+1),w=ko(this,t,Ks,c,b,v,y);w&&e.push(w)}if(this.isLineLoop){let y=h.getX(m-1),g=h.getX(f),b=ko(this,t,Ks,c,y,g,m-1);b&&e.push(b)}}else{let f=Math.max(0,r.start),m=Math.min(d.count,r.start+r.count);for(let y=f,g=m-1;y<g;y+=l){let b=ko(this,t,Ks,c,y,y+1,y);b&&e.push(b)}if(this.isLineLoop){let y=ko(this,t,Ks,c,m-1,f,m-1);y&&e.push(y)}}}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};zf=new F,Vf=new F,as=class extends ya{constructor(t,e){super(t,e),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let t=this.geometry;if(t.index===null){let e=t.attributes.position,n=[];for(let a=0,s=e.count;a<s;a+=2)zf.fromBufferAttribute(e,a),Vf.fromBufferAttribute(e,a+1),n[a]=a===0?0:n[a-1],n[a+1]=n[a]+zf.distanceTo(Vf);t.setAttribute("lineDistance",new re(n,1))}else Rt("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}},dr=class extends ya{constructor(t,e){super(t,e),this.isLineLoop=!0,this.type="LineLoop"}},hc=class extends ri{constructor(t){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new kt(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.alphaMap=t.alphaMap,this.size=t.size,this.sizeAttenuation=t.sizeAttenuation,this.fog=t.fog,this}},Hf=new Zt,Gh=new Kn,zo=new ze,Vo=new F,ur=class extends Re{constructor(t=new Ae,e=new hc){super(),this.isPoints=!0,this.type="Points",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.matrixWorld,s=t.params.Points.threshold,r=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),zo.copy(n.boundingSphere),zo.applyMatrix4(a),zo.radius+=s,t.ray.intersectsSphere(zo)===!1)return;Hf.copy(a).invert(),Gh.copy(t.ray).applyMatrix4(Hf);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=n.index,u=n.attributes.position;if(l!==null){let d=Math.max(0,r.start),f=Math.min(l.count,r.start+r.count);for(let m=d,y=f;m<y;m++){let g=l.getX(m);Vo.fromBufferAttribute(u,g),Gf(Vo,g,c,a,t,e,this)}}else{let d=Math.max(0,r.start),f=Math.min(u.count,r.start+r.count);for(let m=d,y=f;m<y;m++)Vo.fromBufferAttribute(u,m),Gf(Vo,m,c,a,t,e,this)}}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};fr=class extends vn{constructor(t=[],e=Sa,n,a,s,r,o,c,l,h){super(t,e,n,a,s,r,o,c,l,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(t){this.image=t}},Ni=class extends vn{constructor(t,e,n=Mn,a,s,r,o=we,c=we,l,h=Ii,u=1){if(h!==Ii&&h!==Li)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let d={width:t,height:e,depth:u};super(d,a,s,r,o,c,h,n,l),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(t){return super.copy(t),this.source=new ts(Object.assign({},t.image)),this.compareFunction=t.compareFunction,this}toJSON(t){let e=super.toJSON(t);return e.compareFunction=this.compareFunction,e}},pr=class extends Ni{constructor(t,e=Mn,n=Sa,a,s,r=we,o=we,c,l=Ii){let h={width:t,height:t,depth:1},u=[h,h,h,h,h,h];super(t,t,e,n,a,s,r,o,c,l),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(t){this.image=t}},mr=class extends vn{constructor(t=null){super(),this.sourceTexture=t,this.isExternalTexture=!0}copy(t){return super.copy(t),this.sourceTexture=t.sourceTexture,this}},ss=class i extends Ae{constructor(t=1,e=1,n=1,a=1,s=1,r=1){super(),this.type="BoxGeometry",this.parameters={width:t,height:e,depth:n,widthSegments:a,heightSegments:s,depthSegments:r};let o=this;a=Math.floor(a),s=Math.floor(s),r=Math.floor(r);let c=[],l=[],h=[],u=[],d=0,f=0;m("z","y","x",-1,-1,n,e,t,r,s,0),m("z","y","x",1,-1,n,e,-t,r,s,1),m("x","z","y",1,1,t,n,e,a,r,2),m("x","z","y",1,-1,t,n,-e,a,r,3),m("x","y","z",1,-1,t,e,n,a,s,4),m("x","y","z",-1,-1,t,e,-n,a,s,5),this.setIndex(c),this.setAttribute("position",new re(l,3)),this.setAttribute("normal",new re(h,3)),this.setAttribute("uv",new re(u,2));function m(y,g,b,v,w,p,_,M,x,S,E){let A=p/x,R=_/S,C=p/2,L=_/2,N=M/2,U=x+1,z=S+1,B=0,K=0,W=new F;for(let Y=0;Y<z;Y++){let tt=Y*R-L;for(let gt=0;gt<U;gt++){let It=gt*A-C;W[y]=It*v,W[g]=tt*w,W[b]=N,l.push(W.x,W.y,W.z),W[y]=0,W[g]=0,W[b]=M>0?1:-1,h.push(W.x,W.y,W.z),u.push(gt/x),u.push(1-Y/S),B+=1}}for(let Y=0;Y<S;Y++)for(let tt=0;tt<x;tt++){let gt=d+tt+U*Y,It=d+tt+U*(Y+1),X=d+(tt+1)+U*(Y+1),it=d+(tt+1)+U*Y;c.push(gt,It,it),c.push(It,X,it),K+=6}o.addGroup(f,K,E),f+=K,d+=B}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.width,t.height,t.depth,t.widthSegments,t.heightSegments,t.depthSegments)}},rs=class i extends Ae{constructor(t=1,e=1,n=1,a=32,s=1,r=!1,o=0,c=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:t,radiusBottom:e,height:n,radialSegments:a,heightSegments:s,openEnded:r,thetaStart:o,thetaLength:c};let l=this;a=Math.floor(a),s=Math.floor(s);let h=[],u=[],d=[],f=[],m=0,y=[],g=n/2,b=0;v(),r===!1&&(t>0&&w(!0),e>0&&w(!1)),this.setIndex(h),this.setAttribute("position",new re(u,3)),this.setAttribute("normal",new re(d,3)),this.setAttribute("uv",new re(f,2));function v(){let p=new F,_=new F,M=0,x=(e-t)/n;for(let S=0;S<=s;S++){let E=[],A=S/s,R=A*(e-t)+t;for(let C=0;C<=a;C++){let L=C/a,N=L*c+o,U=Math.sin(N),z=Math.cos(N);_.x=R*U,_.y=-A*n+g,_.z=R*z,u.push(_.x,_.y,_.z),p.set(U,x,z).normalize(),d.push(p.x,p.y,p.z),f.push(L,1-A),E.push(m++)}y.push(E)}for(let S=0;S<a;S++)for(let E=0;E<s;E++){let A=y[E][S],R=y[E+1][S],C=y[E+1][S+1],L=y[E][S+1];(t>0||E!==0)&&(h.push(A,R,L),M+=3),(e>0||E!==s-1)&&(h.push(R,C,L),M+=3)}l.addGroup(b,M,0),b+=M}function w(p){let _=m,M=new Ct,x=new F,S=0,E=p===!0?t:e,A=p===!0?1:-1;for(let C=1;C<=a;C++)u.push(0,g*A,0),d.push(0,A,0),f.push(.5,.5),m++;let R=m;for(let C=0;C<=a;C++){let N=C/a*c+o,U=Math.cos(N),z=Math.sin(N);x.x=E*z,x.y=g*A,x.z=E*U,u.push(x.x,x.y,x.z),d.push(0,A,0),M.x=U*.5+.5,M.y=z*.5*A+.5,f.push(M.x,M.y),m++}for(let C=0;C<a;C++){let L=_+C,N=R+C;p===!0?h.push(N,N+1,L):h.push(N+1,N,L),S+=3}l.addGroup(b,S,p===!0?1:2),b+=S}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radiusTop,t.radiusBottom,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}},gr=class i extends rs{constructor(t=1,e=1,n=32,a=1,s=!1,r=0,o=Math.PI*2){super(0,t,e,n,a,s,r,o),this.type="ConeGeometry",this.parameters={radius:t,height:e,radialSegments:n,heightSegments:a,openEnded:s,thetaStart:r,thetaLength:o}}static fromJSON(t){return new i(t.radius,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}},br=class i extends Ae{constructor(t=1,e=1,n=1,a=1){super(),this.type="PlaneGeometry",this.parameters={width:t,height:e,widthSegments:n,heightSegments:a};let s=t/2,r=e/2,o=Math.floor(n),c=Math.floor(a),l=o+1,h=c+1,u=t/o,d=e/c,f=[],m=[],y=[],g=[];for(let b=0;b<h;b++){let v=b*d-r;for(let w=0;w<l;w++){let p=w*u-s;m.push(p,-v,0),y.push(0,0,1),g.push(w/o),g.push(1-b/c)}}for(let b=0;b<c;b++)for(let v=0;v<o;v++){let w=v+l*b,p=v+l*(b+1),_=v+1+l*(b+1),M=v+1+l*b;f.push(w,p,M),f.push(p,_,M)}this.setIndex(f),this.setAttribute("position",new re(m,3)),this.setAttribute("normal",new re(y,3)),this.setAttribute("uv",new re(g,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.width,t.height,t.widthSegments,t.heightSegments)}},xr=class i extends Ae{constructor(t=1,e=32,n=16,a=0,s=Math.PI*2,r=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:t,widthSegments:e,heightSegments:n,phiStart:a,phiLength:s,thetaStart:r,thetaLength:o},e=Math.max(3,Math.floor(e)),n=Math.max(2,Math.floor(n));let c=Math.min(r+o,Math.PI),l=0,h=[],u=new F,d=new F,f=[],m=[],y=[],g=[];for(let b=0;b<=n;b++){let v=[],w=b/n,p=r+w*o,_=t*Math.cos(p),M=Math.sqrt(t*t-_*_),x=0;b===0&&r===0?x=.5/e:b===n&&c===Math.PI&&(x=-.5/e);for(let S=0;S<=e;S++){let E=S/e,A=a+E*s;u.x=-M*Math.cos(A),u.y=_,u.z=M*Math.sin(A),m.push(u.x,u.y,u.z),d.copy(u).normalize(),y.push(d.x,d.y,d.z),g.push(E+x,1-w),v.push(l++)}h.push(v)}for(let b=0;b<n;b++)for(let v=0;v<e;v++){let w=h[b][v+1],p=h[b][v],_=h[b+1][v],M=h[b+1][v+1];(b!==0||r>0)&&f.push(w,p,M),(b!==n-1||c<Math.PI)&&f.push(p,_,M)}this.setIndex(f),this.setAttribute("position",new re(m,3)),this.setAttribute("normal",new re(y,3)),this.setAttribute("uv",new re(g,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radius,t.widthSegments,t.heightSegments,t.phiStart,t.phiLength,t.thetaStart,t.thetaLength)}},yr=class i extends Ae{constructor(t=1,e=.4,n=12,a=48,s=Math.PI*2,r=0,o=Math.PI*2){super(),this.type="TorusGeometry",this.parameters={radius:t,tube:e,radialSegments:n,tubularSegments:a,arc:s,thetaStart:r,thetaLength:o},n=Math.floor(n),a=Math.floor(a);let c=[],l=[],h=[],u=[],d=new F,f=new F,m=new F;for(let y=0;y<=n;y++){let g=r+y/n*o;for(let b=0;b<=a;b++){let v=b/a*s;f.x=(t+e*Math.cos(g))*Math.cos(v),f.y=(t+e*Math.cos(g))*Math.sin(v),f.z=e*Math.sin(g),l.push(f.x,f.y,f.z),d.x=t*Math.cos(v),d.y=t*Math.sin(v),m.subVectors(f,d).normalize(),h.push(m.x,m.y,m.z),u.push(b/a),u.push(y/n)}}for(let y=1;y<=n;y++)for(let g=1;g<=a;g++){let b=(a+1)*y+g-1,v=(a+1)*(y-1)+g-1,w=(a+1)*(y-1)+g,p=(a+1)*y+g;c.push(b,v,p),c.push(v,w,p)}this.setIndex(c),this.setAttribute("position",new re(l,3)),this.setAttribute("normal",new re(h,3)),this.setAttribute("uv",new re(u,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radius,t.tube,t.radialSegments,t.tubularSegments,t.arc,t.thetaStart,t.thetaLength)}},_r=class extends Ae{constructor(t=null){if(super(),this.type="WireframeGeometry",this.parameters={geometry:t},t!==null){let e=[],n=new Set,a=new F,s=new F;if(t.index!==null){let r=t.attributes.position,o=t.index,c=t.groups;c.length===0&&(c=[{start:0,count:o.count,materialIndex:0}]);for(let l=0,h=c.length;l<h;++l){let u=c[l],d=u.start,f=u.count;for(let m=d,y=d+f;m<y;m+=3)for(let g=0;g<3;g++){let b=o.getX(m+g),v=o.getX(m+(g+1)%3);a.fromBufferAttribute(r,b),s.fromBufferAttribute(r,v),Wf(a,s,n)===!0&&(e.push(a.x,a.y,a.z),e.push(s.x,s.y,s.z))}}}else{let r=t.attributes.position;for(let o=0,c=r.count/3;o<c;o++)for(let l=0;l<3;l++){let h=3*o+l,u=3*o+(l+1)%3;a.fromBufferAttribute(r,h),s.fromBufferAttribute(r,u),Wf(a,s,n)===!0&&(e.push(a.x,a.y,a.z),e.push(s.x,s.y,s.z))}}this.setAttribute("position",new re(e,3))}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}};Gr={clone:Ta,merge:nn},Qx=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,t0=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,Bn=class extends ri{constructor(t){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=Qx,this.fragmentShader=t0,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,t!==void 0&&this.setValues(t)}copy(t){return super.copy(t),this.fragmentShader=t.fragmentShader,this.vertexShader=t.vertexShader,this.uniforms=Ta(t.uniforms),this.uniformsGroups=$x(t.uniformsGroups),this.defines=Object.assign({},t.defines),this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.fog=t.fog,this.lights=t.lights,this.clipping=t.clipping,this.extensions=Object.assign({},t.extensions),this.glslVersion=t.glslVersion,this.defaultAttributeValues=Object.assign({},t.defaultAttributeValues),this.index0AttributeName=t.index0AttributeName,this.uniformsNeedUpdate=t.uniformsNeedUpdate,this}toJSON(t){let e=super.toJSON(t);e.glslVersion=this.glslVersion,e.uniforms={};for(let a in this.uniforms){let r=this.uniforms[a].value;r&&r.isTexture?e.uniforms[a]={type:"t",value:r.toJSON(t).uuid}:r&&r.isColor?e.uniforms[a]={type:"c",value:r.getHex()}:r&&r.isVector2?e.uniforms[a]={type:"v2",value:r.toArray()}:r&&r.isVector3?e.uniforms[a]={type:"v3",value:r.toArray()}:r&&r.isVector4?e.uniforms[a]={type:"v4",value:r.toArray()}:r&&r.isMatrix3?e.uniforms[a]={type:"m3",value:r.toArray()}:r&&r.isMatrix4?e.uniforms[a]={type:"m4",value:r.toArray()}:e.uniforms[a]={value:r}}Object.keys(this.defines).length>0&&(e.defines=this.defines),e.vertexShader=this.vertexShader,e.fragmentShader=this.fragmentShader,e.lights=this.lights,e.clipping=this.clipping;let n={};for(let a in this.extensions)this.extensions[a]===!0&&(n[a]=!0);return Object.keys(n).length>0&&(e.extensions=n),e}fromJSON(t,e){if(super.fromJSON(t,e),t.uniforms!==void 0)for(let n in t.uniforms){let a=t.uniforms[n];switch(this.uniforms[n]={},a.type){case"t":this.uniforms[n].value=e[a.value]||null;break;case"c":this.uniforms[n].value=new kt().setHex(a.value);break;case"v2":this.uniforms[n].value=new Ct().fromArray(a.value);break;case"v3":this.uniforms[n].value=new F().fromArray(a.value);break;case"v4":this.uniforms[n].value=new $t().fromArray(a.value);break;case"m3":this.uniforms[n].value=new Dt().fromArray(a.value);break;case"m4":this.uniforms[n].value=new Zt().fromArray(a.value);break;default:this.uniforms[n].value=a.value}}if(t.defines!==void 0&&(this.defines=t.defines),t.vertexShader!==void 0&&(this.vertexShader=t.vertexShader),t.fragmentShader!==void 0&&(this.fragmentShader=t.fragmentShader),t.glslVersion!==void 0&&(this.glslVersion=t.glslVersion),t.extensions!==void 0)for(let n in t.extensions)this.extensions[n]=t.extensions[n];return t.lights!==void 0&&(this.lights=t.lights),t.clipping!==void 0&&(this.clipping=t.clipping),this}},dc=class extends Bn{constructor(t){super(t),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}},vr=class extends ri{constructor(t){super(),this.isMeshLambertMaterial=!0,this.type="MeshLambertMaterial",this.color=new kt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new kt(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=hl,this.normalScale=new Ct(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ri,this.combine=Ic,this.reflectivity=1,this.envMapIntensity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.emissive.copy(t.emissive),this.emissiveMap=t.emissiveMap,this.emissiveIntensity=t.emissiveIntensity,this.bumpMap=t.bumpMap,this.bumpScale=t.bumpScale,this.normalMap=t.normalMap,this.normalMapType=t.normalMapType,this.normalScale.copy(t.normalScale),this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.envMapIntensity=t.envMapIntensity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.flatShading=t.flatShading,this.fog=t.fog,this}},uc=class extends ri{constructor(t){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=Ap,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(t)}copy(t){return super.copy(t),this.depthPacking=t.depthPacking,this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this}},fc=class extends ri{constructor(t){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(t)}copy(t){return super.copy(t),this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this}};Yi=class{constructor(t,e,n,a){this.parameterPositions=t,this._cachedIndex=0,this.resultBuffer=a!==void 0?a:new e.constructor(n),this.sampleValues=e,this.valueSize=n,this.settings=null,this.DefaultSettings_={}}evaluate(t){let e=this.parameterPositions,n=this._cachedIndex,a=e[n],s=e[n-1];n:{t:{let r;e:{i:if(!(t<a)){for(let o=n+2;;){if(a===void 0){if(t<s)break i;return n=e.length,this._cachedIndex=n,this.copySampleValue_(n-1)}if(n===o)break;if(s=a,a=e[++n],t<a)break t}r=e.length;break e}if(!(t>=s)){let o=e[1];t<o&&(n=2,s=o);for(let c=n-2;;){if(s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(n===c)break;if(a=s,s=e[--n-1],t>=s)break t}r=n,n=0;break e}break n}for(;n<r;){let o=n+r>>>1;t<e[o]?r=o:n=o+1}if(a=e[n],s=e[n-1],s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(a===void 0)return n=e.length,this._cachedIndex=n,this.copySampleValue_(n-1)}this._cachedIndex=n,this.intervalChanged_(n,s,a)}return this.interpolate_(n,s,t,a)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(t){let e=this.resultBuffer,n=this.sampleValues,a=this.valueSize,s=t*a;for(let r=0;r!==a;++r)e[r]=n[s+r];return e}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},pc=class extends Yi{constructor(t,e,n,a){super(t,e,n,a),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:kh,endingEnd:kh}}intervalChanged_(t,e,n){let a=this.parameterPositions,s=t-2,r=t+1,o=a[s],c=a[r];if(o===void 0)switch(this.getSettings_().endingStart){case zh:s=t,o=2*e-n;break;case Vh:s=a.length-2,o=e+a[s]-a[s+1];break;default:s=t,o=n}if(c===void 0)switch(this.getSettings_().endingEnd){case zh:r=t,c=2*n-e;break;case Vh:r=1,c=n+a[1]-a[0];break;default:r=t-1,c=e}let l=(n-e)*.5,h=this.valueSize;this._weightPrev=l/(e-o),this._weightNext=l/(c-n),this._offsetPrev=s*h,this._offsetNext=r*h}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=this._offsetPrev,u=this._offsetNext,d=this._weightPrev,f=this._weightNext,m=(n-e)/(a-e),y=m*m,g=y*m,b=-d*g+2*d*y-d*m,v=(1+d)*g+(-1.5-2*d)*y+(-.5+d)*m+1,w=(-1-f)*g+(1.5+f)*y+.5*m,p=f*g-f*y;for(let _=0;_!==o;++_)s[_]=b*r[h+_]+v*r[l+_]+w*r[c+_]+p*r[u+_];return s}},mc=class extends Yi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=(n-e)/(a-e),u=1-h;for(let d=0;d!==o;++d)s[d]=r[l+d]*u+r[c+d]*h;return s}},gc=class extends Yi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t){return this.copySampleValue_(t-1)}},bc=class extends Yi{interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=this.inTangents,u=this.outTangents;if(!h||!u){let m=(n-e)/(a-e),y=1-m;for(let g=0;g!==o;++g)s[g]=r[l+g]*y+r[c+g]*m;return s}let d=o*2,f=t-1;for(let m=0;m!==o;++m){let y=r[l+m],g=r[c+m],b=f*d+m*2,v=u[b],w=u[b+1],p=t*d+m*2,_=h[p],M=h[p+1],x=n0(n,e,v,_,a);s[m]=Bp(x,y,w,M,g)}return s}};Rn=class{constructor(t,e,n,a){if(t===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(e===void 0||e.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+t);this.name=t,this.times=Wa(e,this.TimeBufferType),this.values=Wa(n,this.ValueBufferType),this.setInterpolation(a||this.DefaultInterpolation)}static toJSON(t){let e=t.constructor,n;if(e.toJSON!==this.toJSON)n=e.toJSON(t);else{n={name:t.name,times:Wa(t.times,Array),values:Wa(t.values,Array)};let a=t.getInterpolation();a!==t.DefaultInterpolation&&(n.interpolation=a),Ho(t.settings)&&(n.settings={inTangents:Wa(t.settings.inTangents,Array),outTangents:Wa(t.settings.outTangents,Array)})}return n.type=t.ValueTypeName,n}InterpolantFactoryMethodDiscrete(t){return new gc(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodLinear(t){return new mc(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodSmooth(t){return new pc(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodBezier(t){let e=new bc(this.times,this.values,this.getValueSize(),t);return this.settings&&(e.inTangents=this.settings.inTangents,e.outTangents=this.settings.outTangents),e}setInterpolation(t){let e;switch(t){case tr:e=this.InterpolantFactoryMethodDiscrete;break;case ic:e=this.InterpolantFactoryMethodLinear;break;case Xo:e=this.InterpolantFactoryMethodSmooth;break;case Bh:e=this.InterpolantFactoryMethodBezier;break}if(e===void 0){let n="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(t!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(n);return Rt("KeyframeTrack:",n),this}return this.createInterpolant=e,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return tr;case this.InterpolantFactoryMethodLinear:return ic;case this.InterpolantFactoryMethodSmooth:return Xo;case this.InterpolantFactoryMethodBezier:return Bh}}getValueSize(){return this.values.length/this.times.length}shift(t){if(t!==0){let e=this.times;for(let n=0,a=e.length;n!==a;++n)e[n]+=t;Ho(this.settings)&&(Xf(this.settings.inTangents,t),Xf(this.settings.outTangents,t))}return this}scale(t){if(t!==1){let e=this.times;for(let n=0,a=e.length;n!==a;++n)e[n]*=t;Ho(this.settings)&&(qf(this.settings.inTangents,t),qf(this.settings.outTangents,t))}return this}trim(t,e){let n=this.times,a=n.length,s=0,r=a-1;for(;s!==a&&n[s]<t;)++s;for(;r!==-1&&n[r]>e;)--r;if(++r,s!==0||r!==a){s>=r&&(r=Math.max(r,1),s=r-1);let o=this.getValueSize();this.times=n.slice(s,r),this.values=this.values.slice(s*o,r*o)}return this}validate(){let t=!0,e=this.getValueSize();e-Math.floor(e)!==0&&(Lt("KeyframeTrack: Invalid value size in track.",this),t=!1);let n=this.times,a=this.values,s=n.length;s===0&&(Lt("KeyframeTrack: Track is empty.",this),t=!1);let r=null;for(let o=0;o!==s;o++){let c=n[o];if(typeof c=="number"&&isNaN(c)){Lt("KeyframeTrack: Time is not a valid number.",this,o,c),t=!1;break}if(r!==null&&r>c){Lt("KeyframeTrack: Out of order keys.",this,o,c,r),t=!1;break}r=c}if(a!==void 0&&dx(a))for(let o=0,c=a.length;o!==c;++o){let l=a[o];if(isNaN(l)){Lt("KeyframeTrack: Value is not a valid number.",this,o,l),t=!1;break}}return t}optimize(){let t=this.times.slice(),e=this.values.slice(),n=this.getValueSize(),a=this.getInterpolation()===Xo,s=t.length-1,r=1;for(let o=1;o<s;++o){let c=!1,l=t[o],h=t[o+1];if(l!==h&&(o!==1||l!==t[0]))if(a)c=!0;else{let u=o*n,d=u-n,f=u+n;for(let m=0;m!==n;++m){let y=e[u+m];if(y!==e[d+m]||y!==e[f+m]){c=!0;break}}}if(c){if(o!==r){t[r]=t[o];let u=o*n,d=r*n;for(let f=0;f!==n;++f)e[d+f]=e[u+f]}++r}}if(s>0){t[r]=t[s];for(let o=s*n,c=r*n,l=0;l!==n;++l)e[c+l]=e[o+l];++r}return r!==t.length?(this.times=t.slice(0,r),this.values=e.slice(0,r*n)):(this.times=t,this.values=e),this}clone(){let t=this.times.slice(),e=this.values.slice(),n=this.constructor,a=new n(this.name,t,e);return a.createInterpolant=this.createInterpolant,Ho(this.settings)&&(a.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),a}};Rn.prototype.ValueTypeName="";Rn.prototype.TimeBufferType=Float32Array;Rn.prototype.ValueBufferType=Float32Array;Rn.prototype.DefaultInterpolation=ic;Ji=class extends Rn{constructor(t,e,n){super(t,e,n)}};Ji.prototype.ValueTypeName="bool";Ji.prototype.ValueBufferType=Array;Ji.prototype.DefaultInterpolation=tr;Ji.prototype.InterpolantFactoryMethodLinear=void 0;Ji.prototype.InterpolantFactoryMethodSmooth=void 0;xc=class extends Rn{constructor(t,e,n,a){super(t,e,n,a)}};xc.prototype.ValueTypeName="color";yc=class extends Rn{constructor(t,e,n,a){super(t,e,n,a)}};yc.prototype.ValueTypeName="number";_c=class extends Yi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=(n-e)/(a-e),l=t*o;for(let h=l+o;l!==h;l+=4)Tn.slerpFlat(s,0,r,l-o,r,l,c);return s}},Mr=class extends Rn{constructor(t,e,n,a){super(t,e,n,a)}InterpolantFactoryMethodLinear(t){return new _c(this.times,this.values,this.getValueSize(),t)}};Mr.prototype.ValueTypeName="quaternion";Mr.prototype.InterpolantFactoryMethodSmooth=void 0;Ki=class extends Rn{constructor(t,e,n){super(t,e,n)}};Ki.prototype.ValueTypeName="string";Ki.prototype.ValueBufferType=Array;Ki.prototype.DefaultInterpolation=tr;Ki.prototype.InterpolantFactoryMethodLinear=void 0;Ki.prototype.InterpolantFactoryMethodSmooth=void 0;vc=class extends Rn{constructor(t,e,n,a){super(t,e,n,a)}};vc.prototype.ValueTypeName="vector";Mc=class{constructor(t,e,n){let a=this,s=!1,r=0,o=0,c,l=[];this.onStart=void 0,this.onLoad=t,this.onProgress=e,this.onError=n,this._abortController=null,this.itemStart=function(h){o++,s===!1&&a.onStart!==void 0&&a.onStart(h,r,o),s=!0},this.itemEnd=function(h){r++,a.onProgress!==void 0&&a.onProgress(h,r,o),r===o&&(s=!1,a.onLoad!==void 0&&a.onLoad())},this.itemError=function(h){a.onError!==void 0&&a.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),c?c(h):h},this.setURLModifier=function(h){return c=h,this},this.addHandler=function(h,u){return l.push(h,u),this},this.removeHandler=function(h){let u=l.indexOf(h);return u!==-1&&l.splice(u,2),this},this.getHandler=function(h){for(let u=0,d=l.length;u<d;u+=2){let f=l[u],m=l[u+1];if(f.global&&(f.lastIndex=0),f.test(h))return m}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},kp=new Mc,Sc=class{constructor(t){this.manager=t!==void 0?t:kp,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(t,e){let n=this;return new Promise(function(a,s){n.load(t,a,e,s)})}parse(){}setCrossOrigin(t){return this.crossOrigin=t,this}setWithCredentials(t){return this.withCredentials=t,this}setPath(t){return this.path=t,this}setResourcePath(t){return this.resourcePath=t,this}setRequestHeader(t){return this.requestHeader=t,this}setPriority(t){return this.priority=t,this}setCache(t){return this.cache=t,this}abort(){return this}};Sc.DEFAULT_MATERIAL_NAME="__DEFAULT";Sr=class extends Re{static registerNode(t){this.prototype._lightNode=t}constructor(t,e=1){super(),this.isLight=!0,this.type="Light",this.color=new kt(t),this.intensity=e}copy(t,e){return super.copy(t,e),this.color.copy(t.color),this.intensity=t.intensity,this}toJSON(t){let e=super.toJSON(t);return e.object.color=this.color.getHex(),e.object.intensity=this.intensity,e}},Oh=new Zt,Yf=new F,Jf=new F,wc=class{constructor(t){this.camera=t,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Ct(512,512),this.mapType=en,this.map=null,this.mapPass=null,this.matrix=new Zt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Ci,this._frameExtents=new Ct(1,1),this._viewportCount=1,this._viewports=[new $t(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(t){let e=this.camera;Yf.setFromMatrixPosition(t.matrixWorld),e.position.copy(Yf),Jf.setFromMatrixPosition(t.target.matrixWorld),e.lookAt(Jf),e.updateMatrixWorld(),this._updateMatrix(e,this.matrix,this._frustum)}_updateMatrix(t,e,n,a){Oh.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse),n.setFromProjectionMatrix(Oh,t.coordinateSystem,t.reversedDepth);let s=this._frameExtents,r=a?a.z/s.x:1,o=a?a.w/s.y:1,c=a?a.x/s.x:0,l=a?a.y/s.y:0;t.coordinateSystem===Za||t.reversedDepth?e.set(.5*r,0,0,.5*r+c,0,.5*o,0,.5*o+l,0,0,1,0,0,0,0,1):e.set(.5*r,0,0,.5*r+c,0,.5*o,0,.5*o+l,0,0,.5,.5,0,0,0,1),e.multiply(Oh)}getViewport(t){return this._viewports[t]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(t){return this.camera=t.camera.clone(),this.intensity=t.intensity,this.bias=t.bias,this.radius=t.radius,this.autoUpdate=t.autoUpdate,this.needsUpdate=t.needsUpdate,this.normalBias=t.normalBias,this.blurSamples=t.blurSamples,this.mapSize.copy(t.mapSize),this.mapType=t.mapType,this.biasNode=t.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){let t={};return t.intensity=this.intensity,t.bias=this.bias,t.normalBias=this.normalBias,t.radius=this.radius,t.blurSamples=this.blurSamples,t.mapSize=this.mapSize.toArray(),t.mapType=this.mapType,t.camera=this.camera.toJSON(!1).object,delete t.camera.matrix,t}},Go=new F,Wo=new Tn,ii=new F,wr=class extends Re{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Zt,this.projectionMatrix=new Zt,this.projectionMatrixInverse=new Zt,this.coordinateSystem=Fn,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(t,e){return super.copy(t,e),this.matrixWorldInverse.copy(t.matrixWorldInverse),this.projectionMatrix.copy(t.projectionMatrix),this.projectionMatrixInverse.copy(t.projectionMatrixInverse),this.coordinateSystem=t.coordinateSystem,this}getWorldDirection(t){return super.getWorldDirection(t).negate()}updateMatrixWorld(t){super.updateMatrixWorld(t),this.matrixWorld.decompose(Go,Wo,ii),ii.x===1&&ii.y===1&&ii.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(Go,Wo,ii.set(1,1,1)).invert()}updateWorldMatrix(t,e,n=!1){super.updateWorldMatrix(t,e,n),this.matrixWorld.decompose(Go,Wo,ii),ii.x===1&&ii.y===1&&ii.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(Go,Wo,ii.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},qi=new F,Kf=new Ct,Zf=new Ct,dn=class extends wr{constructor(t=50,e=1,n=.1,a=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=t,this.zoom=1,this.near=n,this.far=a,this.focus=10,this.aspect=e,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.fov=t.fov,this.zoom=t.zoom,this.near=t.near,this.far=t.far,this.focus=t.focus,this.aspect=t.aspect,this.view=t.view===null?null:Object.assign({},t.view),this.filmGauge=t.filmGauge,this.filmOffset=t.filmOffset,this}setFocalLength(t){let e=.5*this.getFilmHeight()/t;this.fov=Qa*2*Math.atan(e),this.updateProjectionMatrix()}getFocalLength(){let t=Math.tan($s*.5*this.fov);return .5*this.getFilmHeight()/t}getEffectiveFOV(){return Qa*2*Math.atan(Math.tan($s*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(t,e,n){qi.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),e.set(qi.x,qi.y).multiplyScalar(-t/qi.z),qi.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(qi.x,qi.y).multiplyScalar(-t/qi.z)}getViewSize(t,e){return this.getViewBounds(t,Kf,Zf),e.subVectors(Zf,Kf)}setViewOffset(t,e,n,a,s,r){this.aspect=t/e,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=a,this.view.width=s,this.view.height=r,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let t=this.near,e=t*Math.tan($s*.5*this.fov)/this.zoom,n=2*e,a=this.aspect*n,s=-.5*a,r=this.view;if(this.view!==null&&this.view.enabled){let c=r.fullWidth,l=r.fullHeight;s+=r.offsetX*a/c,e-=r.offsetY*n/l,a*=r.width/c,n*=r.height/l}let o=this.filmOffset;o!==0&&(s+=t*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(s,s+a,e,e-n,t,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){let e=super.toJSON(t);return e.object.fov=this.fov,e.object.zoom=this.zoom,e.object.near=this.near,e.object.far=this.far,e.object.focus=this.focus,e.object.aspect=this.aspect,this.view!==null&&(e.object.view=Object.assign({},this.view)),e.object.filmGauge=this.filmGauge,e.object.filmOffset=this.filmOffset,e}},Ar=class extends wr{constructor(t=-1,e=1,n=1,a=-1,s=.1,r=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=t,this.right=e,this.top=n,this.bottom=a,this.near=s,this.far=r,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.left=t.left,this.right=t.right,this.top=t.top,this.bottom=t.bottom,this.near=t.near,this.far=t.far,this.zoom=t.zoom,this.view=t.view===null?null:Object.assign({},t.view),this}setViewOffset(t,e,n,a,s,r){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=a,this.view.width=s,this.view.height=r,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let t=(this.right-this.left)/(2*this.zoom),e=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,a=(this.top+this.bottom)/2,s=n-t,r=n+t,o=a+e,c=a-e;if(this.view!==null&&this.view.enabled){let l=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;s+=l*this.view.offsetX,r=s+l*this.view.width,o-=h*this.view.offsetY,c=o-h*this.view.height}this.projectionMatrix.makeOrthographic(s,r,o,c,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){let e=super.toJSON(t);return e.object.zoom=this.zoom,e.object.left=this.left,e.object.right=this.right,e.object.top=this.top,e.object.bottom=this.bottom,e.object.near=this.near,e.object.far=this.far,this.view!==null&&(e.object.view=Object.assign({},this.view)),e}},Wh=class extends wc{constructor(){super(new Ar(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}},Er=class extends Sr{constructor(t,e){super(t,e),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Re.DEFAULT_UP),this.updateMatrix(),this.target=new Re,this.shadow=new Wh}dispose(){super.dispose(),this.shadow.dispose()}copy(t){return super.copy(t),this.target=t.target.clone(),this.shadow=t.shadow.clone(),this}toJSON(t){let e=super.toJSON(t);return e.object.shadow=this.shadow.toJSON(),e.object.target=this.target.uuid,e}},Tr=class extends Sr{constructor(t,e){super(t,e),this.isAmbientLight=!0,this.type="AmbientLight"}},Ir=class extends Ae{constructor(){super(),this.isInstancedBufferGeometry=!0,this.type="InstancedBufferGeometry",this.instanceCount=1/0}copy(t){return super.copy(t),this.instanceCount=t.instanceCount,this}toJSON(){let t=super.toJSON();return t.instanceCount=this.instanceCount,t.isInstancedBufferGeometry=!0,t}},ja=-90,Xa=1,os=class extends Re{constructor(t,e,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;let a=new dn(ja,Xa,t,e);a.layers=this.layers,this.add(a);let s=new dn(ja,Xa,t,e);s.layers=this.layers,this.add(s);let r=new dn(ja,Xa,t,e);r.layers=this.layers,this.add(r);let o=new dn(ja,Xa,t,e);o.layers=this.layers,this.add(o);let c=new dn(ja,Xa,t,e);c.layers=this.layers,this.add(c);let l=new dn(ja,Xa,t,e);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){let t=this.coordinateSystem,e=this.children.concat(),[n,a,s,r,o,c]=e;for(let l of e)this.remove(l);if(t===Fn)n.up.set(0,1,0),n.lookAt(1,0,0),a.up.set(0,1,0),a.lookAt(-1,0,0),s.up.set(0,0,-1),s.lookAt(0,1,0),r.up.set(0,0,1),r.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(t===Za)n.up.set(0,-1,0),n.lookAt(-1,0,0),a.up.set(0,-1,0),a.lookAt(1,0,0),s.up.set(0,0,1),s.lookAt(0,1,0),r.up.set(0,0,-1),r.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+t);for(let l of e)this.add(l),l.updateMatrixWorld()}update(t,e){this.parent===null&&this.updateMatrixWorld();let{renderTarget:n,activeMipmapLevel:a}=this;this.coordinateSystem!==t.coordinateSystem&&(this.coordinateSystem=t.coordinateSystem,this.updateCoordinateSystem());let[s,r,o,c,l,h]=this.children,u=t.getRenderTarget(),d=t.getActiveCubeFace(),f=t.getActiveMipmapLevel(),m=t.xr.enabled;t.xr.enabled=!1;let y=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let g=!1;t.isWebGLRenderer===!0?g=t.state.buffers.depth.getReversed():g=t.reversedDepthBuffer,t.setRenderTarget(n,0,a),g&&t.autoClear===!1&&t.clearDepth(),t.render(e,s),t.setRenderTarget(n,1,a),g&&t.autoClear===!1&&t.clearDepth(),t.render(e,r),t.setRenderTarget(n,2,a),g&&t.autoClear===!1&&t.clearDepth(),t.render(e,o),t.setRenderTarget(n,3,a),g&&t.autoClear===!1&&t.clearDepth(),t.render(e,c),t.setRenderTarget(n,4,a),g&&t.autoClear===!1&&t.clearDepth(),t.render(e,l),n.texture.mipmapsAutoUpdate=y,t.setRenderTarget(n,5,a),g&&t.autoClear===!1&&t.clearDepth(),t.render(e,h),t.setRenderTarget(u,d,f),t.xr.enabled=m,n.texture.needsPMREMUpdate=!0}},Ac=class extends dn{constructor(t=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=t,this.perCameraFrustumCulled=!1}},Md="\\[\\]\\.:\\/",i0=new RegExp("["+Md+"]","g"),Sd="[^"+Md+"]",a0="[^"+Md.replace("\\.","")+"]",s0=/((?:WC+[\/:])*)/.source.replace("WC",Sd),r0=/(WCOD+)?/.source.replace("WCOD",a0),o0=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",Sd),c0=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",Sd),l0=new RegExp("^"+s0+r0+o0+c0+"$"),h0=["material","materials","bones","map"],jh=class{constructor(t,e,n){let a=n||fe.parseTrackName(e);this._targetGroup=t,this._bindings=t.subscribe_(e,a)}getValue(t,e){this.bind();let n=this._targetGroup.nCachedObjects_,a=this._bindings[n];a!==void 0&&a.getValue(t,e)}setValue(t,e){let n=this._bindings;for(let a=this._targetGroup.nCachedObjects_,s=n.length;a!==s;++a)n[a].setValue(t,e)}bind(){let t=this._bindings;for(let e=this._targetGroup.nCachedObjects_,n=t.length;e!==n;++e)t[e].bind()}unbind(){let t=this._bindings;for(let e=this._targetGroup.nCachedObjects_,n=t.length;e!==n;++e)t[e].unbind()}},fe=class i{constructor(t,e,n){this.path=e,this.parsedPath=n||i.parseTrackName(e),this.node=i.findNode(t,this.parsedPath.nodeName),this.rootNode=t,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(t,e,n){return t&&t.isAnimationObjectGroup?new i.Composite(t,e,n):new i(t,e,n)}static sanitizeNodeName(t){return t.replace(/\s/g,"_").replace(i0,"")}static parseTrackName(t){let e=l0.exec(t);if(e===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+t);let n={nodeName:e[2],objectName:e[3],objectIndex:e[4],propertyName:e[5],propertyIndex:e[6]},a=n.nodeName&&n.nodeName.lastIndexOf(".");if(a!==void 0&&a!==-1){let s=n.nodeName.substring(a+1);h0.indexOf(s)!==-1&&(n.nodeName=n.nodeName.substring(0,a),n.objectName=s)}if(n.propertyName===null||n.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+t);return n}static findNode(t,e){if(e===void 0||e===""||e==="."||e===-1||e===t.name||e===t.uuid)return t;if(t.skeleton){let n=t.skeleton.getBoneByName(e);if(n!==void 0)return n}if(t.children){let n=function(s){for(let r=0;r<s.length;r++){let o=s[r];if(o.name===e||o.uuid===e)return o;let c=n(o.children);if(c)return c}return null},a=n(t.children);if(a)return a}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(t,e){t[e]=this.targetObject[this.propertyName]}_getValue_array(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)t[e++]=n[a]}_getValue_arrayElement(t,e){t[e]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(t,e){this.resolvedProperty.toArray(t,e)}_setValue_direct(t,e){this.targetObject[this.propertyName]=t[e]}_setValue_direct_setNeedsUpdate(t,e){this.targetObject[this.propertyName]=t[e],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(t,e){this.targetObject[this.propertyName]=t[e],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++]}_setValue_array_setNeedsUpdate(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(t,e){this.resolvedProperty[this.propertyIndex]=t[e]}_setValue_arrayElement_setNeedsUpdate(t,e){this.resolvedProperty[this.propertyIndex]=t[e],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(t,e){this.resolvedProperty[this.propertyIndex]=t[e],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(t,e){this.resolvedProperty.fromArray(t,e)}_setValue_fromArray_setNeedsUpdate(t,e){this.resolvedProperty.fromArray(t,e),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(t,e){this.resolvedProperty.fromArray(t,e),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(t,e){this.bind(),this.getValue(t,e)}_setValue_unbound(t,e){this.bind(),this.setValue(t,e)}bind(){let t=this.node,e=this.parsedPath,n=e.objectName,a=e.propertyName,s=e.propertyIndex;if(t||(t=i.findNode(this.rootNode,e.nodeName),this.node=t),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!t){Rt("PropertyBinding: No target node found for track: "+this.path+".");return}if(n){let l=e.objectIndex;switch(n){case"materials":if(!t.material){Lt("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!t.material.materials){Lt("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}t=t.material.materials;break;case"bones":if(!t.skeleton){Lt("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}t=t.skeleton.bones;for(let h=0;h<t.length;h++)if(t[h].name===l){l=h;break}break;case"map":if("map"in t){t=t.map;break}if(!t.material){Lt("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!t.material.map){Lt("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}t=t.material.map;break;default:if(t[n]===void 0){Lt("PropertyBinding: Can not bind to objectName of node undefined.",this);return}t=t[n]}if(l!==void 0){if(t[l]===void 0){Lt("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,t);return}t=t[l]}}let r=t[a];if(r===void 0){let l=e.nodeName;Lt("PropertyBinding: Trying to update property for track: "+l+"."+a+" but it wasn't found.",t);return}let o=this.Versioning.None;this.targetObject=t,t.isMaterial===!0?o=this.Versioning.NeedsUpdate:t.isObject3D===!0&&(o=this.Versioning.MatrixWorldNeedsUpdate);let c=this.BindingType.Direct;if(s!==void 0){if(a==="morphTargetInfluences"){if(!t.geometry){Lt("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!t.geometry.morphAttributes){Lt("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}t.morphTargetDictionary[s]!==void 0&&(s=t.morphTargetDictionary[s])}c=this.BindingType.ArrayElement,this.resolvedProperty=r,this.propertyIndex=s}else r.fromArray!==void 0&&r.toArray!==void 0?(c=this.BindingType.HasFromToArray,this.resolvedProperty=r):Array.isArray(r)?(c=this.BindingType.EntireArray,this.resolvedProperty=r):this.propertyName=a;this.getValue=this.GetterByBindingType[c],this.setValue=this.SetterByBindingTypeAndVersioning[c][o]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};fe.Composite=jh;fe.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};fe.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};fe.prototype.GetterByBindingType=[fe.prototype._getValue_direct,fe.prototype._getValue_array,fe.prototype._getValue_arrayElement,fe.prototype._getValue_toArray];fe.prototype.SetterByBindingTypeAndVersioning=[[fe.prototype._setValue_direct,fe.prototype._setValue_direct_setNeedsUpdate,fe.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[fe.prototype._setValue_array,fe.prototype._setValue_array_setNeedsUpdate,fe.prototype._setValue_array_setMatrixWorldNeedsUpdate],[fe.prototype._setValue_arrayElement,fe.prototype._setValue_arrayElement_setNeedsUpdate,fe.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[fe.prototype._setValue_fromArray,fe.prototype._setValue_fromArray_setNeedsUpdate,fe.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];BA=new Float32Array(1),Zi=class extends oc{constructor(t,e,n=1){super(t,e),this.isInstancedInterleavedBuffer=!0,this.meshPerAttribute=n}copy(t){return super.copy(t),this.meshPerAttribute=t.meshPerAttribute,this}clone(t){let e=super.clone(t);return e.meshPerAttribute=this.meshPerAttribute,e}toJSON(t){let e=super.toJSON(t);return e.isInstancedInterleavedBuffer=!0,e.meshPerAttribute=this.meshPerAttribute,e}},$f=new Zt,Rr=class{constructor(t,e,n=0,a=1/0){this.ray=new Kn(t,e),this.near=n,this.far=a,this.camera=null,this.layers=new es,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(t,e){this.ray.set(t,e)}setFromCamera(t,e){e.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(t.x,t.y,.5).unproject(e).sub(this.ray.origin).normalize(),this.camera=e):e.isOrthographicCamera?(this.ray.origin.set(t.x,t.y,e.projectionMatrix.elements[14]).unproject(e),this.ray.direction.set(0,0,-1).transformDirection(e.matrixWorld),this.camera=e):Lt("Raycaster: Unsupported camera type: "+e.type)}setFromXRController(t){return $f.identity().extractRotation(t.matrixWorld),this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4($f),this}intersectObject(t,e=!0,n=[]){return Xh(t,this,n,e),n.sort(Qf),n}intersectObjects(t,e=!0,n=[]){for(let a=0,s=t.length;a<s;a++)Xh(t[a],this,n,e);return n.sort(Qf),n}};cs=class{constructor(t=1,e=0,n=0){this.radius=t,this.phi=e,this.theta=n}set(t,e,n){return this.radius=t,this.phi=e,this.theta=n,this}copy(t){return this.radius=t.radius,this.phi=t.phi,this.theta=t.theta,this}makeSafe(){return this.phi=Bt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(t){return this.setFromCartesianCoords(t.x,t.y,t.z)}setFromCartesianCoords(t,e,n){return this.radius=Math.sqrt(t*t+e*e+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(t,n),this.phi=Math.acos(Bt(e/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}},Rd=class Rd{constructor(t,e,n,a){this.elements=[1,0,0,1],t!==void 0&&this.set(t,e,n,a)}identity(){return this.set(1,0,0,1),this}fromArray(t,e=0){for(let n=0;n<4;n++)this.elements[n]=t[n+e];return this}set(t,e,n,a){let s=this.elements;return s[0]=t,s[2]=e,s[1]=n,s[3]=a,this}};Rd.prototype.isMatrix2=!0;qh=Rd,tp=new F,jo=new F,qa=new F,Ya=new F,Fh=new F,d0=new F,u0=new F,_a=class{constructor(t=new F,e=new F){this.start=t,this.end=e}set(t,e){return this.start.copy(t),this.end.copy(e),this}copy(t){return this.start.copy(t.start),this.end.copy(t.end),this}getCenter(t){return t.addVectors(this.start,this.end).multiplyScalar(.5)}delta(t){return t.subVectors(this.end,this.start)}distanceSq(){return this.start.distanceToSquared(this.end)}distance(){return this.start.distanceTo(this.end)}at(t,e){return this.delta(e).multiplyScalar(t).add(this.start)}closestPointToPointParameter(t,e){tp.subVectors(t,this.start),jo.subVectors(this.end,this.start);let n=jo.dot(jo);if(n===0)return 0;let s=jo.dot(tp)/n;return e&&(s=Bt(s,0,1)),s}closestPointToPoint(t,e,n){let a=this.closestPointToPointParameter(t,e);return this.delta(n).multiplyScalar(a).add(this.start)}distanceSqToLine3(t,e=d0,n=u0){let a=10000000000000001e-32,s,r,o=this.start,c=t.start,l=this.end,h=t.end;qa.subVectors(l,o),Ya.subVectors(h,c),Fh.subVectors(o,c);let u=qa.dot(qa),d=Ya.dot(Ya),f=Ya.dot(Fh);if(u<=a&&d<=a)return e.copy(o),n.copy(c),e.distanceToSquared(n);if(u<=a)s=0,r=f/d,r=Bt(r,0,1);else{let m=qa.dot(Fh);if(d<=a)r=0,s=Bt(-m/u,0,1);else{let y=qa.dot(Ya),g=u*d-y*y;g!==0?s=Bt((y*f-m*d)/g,0,1):s=0,r=(y*s+f)/d,r<0?(r=0,s=Bt(-m/u,0,1)):r>1&&(r=1,s=Bt((y-m)/u,0,1))}}return e.copy(o).addScaledVector(qa,s),n.copy(c).addScaledVector(Ya,r),e.distanceToSquared(n)}applyMatrix4(t){return this.start.applyMatrix4(t),this.end.applyMatrix4(t),this}equals(t){return t.start.equals(this.start)&&t.end.equals(this.end)}clone(){return new this.constructor().copy(this)}},Cr=class extends as{constructor(t=10,e=10,n=4473924,a=8947848){n=new kt(n),a=new kt(a);let s=e/2,r=t/e,o=t/2,c=[],l=[];for(let d=0,f=0,m=-o;d<=e;d++,m+=r){c.push(-o,0,m,o,0,m),c.push(m,0,-o,m,0,o);let y=d===s?n:a;y.toArray(l,f),f+=3,y.toArray(l,f),f+=3,y.toArray(l,f),f+=3,y.toArray(l,f),f+=3}let h=new Ae;h.setAttribute("position",new re(c,3)),h.setAttribute("color",new re(l,3));let u=new xa({vertexColors:!0,toneMapped:!1});super(h,u),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}},Nr=class extends Yn{constructor(t,e=null){super(),this.object=t,this.domElement=e,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(t){this.domElement!==null&&this.disconnect(),this.domElement=t}disconnect(){}dispose(){}update(){}};typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?Rt("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187")});function om(){let i=null,t=!1,e=null,n=null;function a(s,r){n=i.requestAnimationFrame(a),e(s,r)}return{start:function(){t!==!0&&e!==null&&i!==null&&(n=i.requestAnimationFrame(a),t=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),t=!1},setAnimationLoop:function(s){e=s},setContext:function(s){i=s}}}function p0(i){let t=new WeakMap;function e(o,c){let l=o.array,h=o.usage,u=l.byteLength,d=i.createBuffer();i.bindBuffer(c,d),i.bufferData(c,l,h),o.onUploadCallback();let f;if(l instanceof Float32Array)f=i.FLOAT;else if(typeof Float16Array<"u"&&l instanceof Float16Array)f=i.HALF_FLOAT;else if(l instanceof Uint16Array)o.isFloat16BufferAttribute?f=i.HALF_FLOAT:f=i.UNSIGNED_SHORT;else if(l instanceof Int16Array)f=i.SHORT;else if(l instanceof Uint32Array)f=i.UNSIGNED_INT;else if(l instanceof Int32Array)f=i.INT;else if(l instanceof Int8Array)f=i.BYTE;else if(l instanceof Uint8Array)f=i.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)f=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:d,type:f,bytesPerElement:l.BYTES_PER_ELEMENT,version:o.version,size:u}}function n(o,c,l){let h=c.array,u=c.updateRanges;if(i.bindBuffer(l,o),u.length===0)i.bufferSubData(l,0,h);else{u.sort((f,m)=>f.start-m.start);let d=0;for(let f=1;f<u.length;f++){let m=u[d],y=u[f];y.start<=m.start+m.count+1?m.count=Math.max(m.count,y.start+y.count-m.start):(++d,u[d]=y)}u.length=d+1;for(let f=0,m=u.length;f<m;f++){let y=u[f];i.bufferSubData(l,y.start*h.BYTES_PER_ELEMENT,h,y.start,y.count)}c.clearUpdateRanges()}c.onUploadCallback()}function a(o){return o.isInterleavedBufferAttribute&&(o=o.data),t.get(o)}function s(o){o.isInterleavedBufferAttribute&&(o=o.data);let c=t.get(o);c&&(i.deleteBuffer(c.buffer),t.delete(o))}function r(o,c){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){let h=t.get(o);(!h||h.version<o.version)&&t.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}let l=t.get(o);if(l===void 0)t.set(o,e(o,c));else if(l.version<o.version){if(l.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(l.buffer,o,c),l.version=o.version}}return{get:a,remove:s,update:r}}function J_(i,t,e,n,a,s){let r=new kt(0),o=a===!0?0:1,c,l,h=null,u=0,d=null;function f(v){let w=v.isScene===!0?v.background:null;if(w&&w.isTexture){let p=v.backgroundBlurriness>0;w=t.get(w,p)}return w}function m(v){let w=!1,p=f(v);p===null?g(r,o):p&&p.isColor&&(g(p,1),w=!0);let _=i.xr.getEnvironmentBlendMode();_==="additive"?e.buffers.color.setClear(0,0,0,1,s):_==="alpha-blend"&&e.buffers.color.setClear(0,0,0,0,s),(i.autoClear||w)&&(e.buffers.depth.setTest(!0),e.buffers.depth.setMask(!0),e.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function y(v,w){let p=f(w);p&&p.isCubeTexture?(l===void 0&&(l=new tn(new ss(1,1,1),new Bn({name:"BackgroundCubeMaterial",uniforms:Ta(gn.backgroundCube.uniforms),vertexShader:gn.backgroundCube.vertexShader,fragmentShader:gn.backgroundCube.fragmentShader,side:Ge,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),l.geometry.deleteAttribute("uv"),l.onBeforeRender=function(_,M,x){this.matrixWorld.copyPosition(x.matrixWorld)},Object.defineProperty(l.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(l)),l.material.uniforms.envMap.value=p,l.material.uniforms.backgroundBlurriness.value=w.backgroundBlurriness,l.material.uniforms.backgroundIntensity.value=w.backgroundIntensity,l.material.uniforms.backgroundRotation.value.setFromMatrix4(Y_.makeRotationFromEuler(w.backgroundRotation)).transpose(),p.isRenderTargetTexture===!1&&l.material.uniforms.backgroundRotation.value.premultiply(cm),l.material.toneMapped=Gt.getTransfer(p.colorSpace)!==ie,(h!==p||u!==p.version||d!==i.toneMapping)&&(l.material.needsUpdate=!0,h=p,u=p.version,d=i.toneMapping),l.layers.enableAll(),v.unshift(l,l.geometry,l.material,0,0,null)):p&&p.isTexture&&(c===void 0&&(c=new tn(new br(2,2),new Bn({name:"BackgroundMaterial",uniforms:Ta(gn.background.uniforms),vertexShader:gn.background.vertexShader,fragmentShader:gn.background.fragmentShader,side:ci,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),Object.defineProperty(c.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(c)),c.material.uniforms.t2D.value=p,c.material.uniforms.backgroundIntensity.value=w.backgroundIntensity,c.material.toneMapped=Gt.getTransfer(p.colorSpace)!==ie,p.matrixAutoUpdate===!0&&p.updateMatrix(),c.material.uniforms.uvTransform.value.copy(p.matrix),(h!==p||u!==p.version||d!==i.toneMapping)&&(c.material.needsUpdate=!0,h=p,u=p.version,d=i.toneMapping),c.layers.enableAll(),v.unshift(c,c.geometry,c.material,0,0,null))}function g(v,w){v.getRGB(ul,vd(i)),e.buffers.color.setClear(ul.r,ul.g,ul.b,w,s)}function b(){l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0),c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0)}return{getClearColor:function(){return r},setClearColor:function(v,w=1){r.set(v),o=w,g(r,o)},getClearAlpha:function(){return o},setClearAlpha:function(v){o=v,g(r,o)},render:m,addToRenderList:y,dispose:b}}function K_(i,t){let e=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},a=d(null),s=a,r=!1;function o(R,C,L,N,U){let z=!1,B=u(R,N,L,C);s!==B&&(s=B,l(s.object)),z=f(R,N,L,U),z&&m(R,N,L,U),U!==null&&t.update(U,i.ELEMENT_ARRAY_BUFFER),(z||r)&&(r=!1,p(R,C,L,N),U!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,t.get(U).buffer))}function c(){return i.createVertexArray()}function l(R){return i.bindVertexArray(R)}function h(R){return i.deleteVertexArray(R)}function u(R,C,L,N){let U=N.wireframe===!0,z=n[C.id];z===void 0&&(z={},n[C.id]=z);let B=R.isInstancedMesh===!0?R.id:0,K=z[B];K===void 0&&(K={},z[B]=K);let W=K[L.id];W===void 0&&(W={},K[L.id]=W);let Y=W[U];return Y===void 0&&(Y=d(c()),W[U]=Y),Y}function d(R){let C=[],L=[],N=[];for(let U=0;U<e;U++)C[U]=0,L[U]=0,N[U]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:C,enabledAttributes:L,attributeDivisors:N,object:R,attributes:{},index:null}}function f(R,C,L,N){let U=s.attributes,z=C.attributes,B=0,K=L.getAttributes();for(let W in K)if(K[W].location>=0){let tt=U[W],gt=z[W];if(gt===void 0&&(W==="instanceMatrix"&&R.instanceMatrix&&(gt=R.instanceMatrix),W==="instanceColor"&&R.instanceColor&&(gt=R.instanceColor)),tt===void 0||tt.attribute!==gt||gt&&tt.data!==gt.data)return!0;B++}return s.attributesNum!==B||s.index!==N}function m(R,C,L,N){let U={},z=C.attributes,B=0,K=L.getAttributes();for(let W in K)if(K[W].location>=0){let tt=z[W];tt===void 0&&(W==="instanceMatrix"&&R.instanceMatrix&&(tt=R.instanceMatrix),W==="instanceColor"&&R.instanceColor&&(tt=R.instanceColor));let gt={};gt.attribute=tt,tt&&tt.data&&(gt.data=tt.data),U[W]=gt,B++}s.attributes=U,s.attributesNum=B,s.index=N}function y(){let R=s.newAttributes;for(let C=0,L=R.length;C<L;C++)R[C]=0}function g(R){b(R,0)}function b(R,C){let L=s.newAttributes,N=s.enabledAttributes,U=s.attributeDivisors;L[R]=1,N[R]===0&&(i.enableVertexAttribArray(R),N[R]=1),U[R]!==C&&(i.vertexAttribDivisor(R,C),U[R]=C)}function v(){let R=s.newAttributes,C=s.enabledAttributes;for(let L=0,N=C.length;L<N;L++)C[L]!==R[L]&&(i.disableVertexAttribArray(L),C[L]=0)}function w(R,C,L,N,U,z,B){B===!0?i.vertexAttribIPointer(R,C,L,U,z):i.vertexAttribPointer(R,C,L,N,U,z)}function p(R,C,L,N){y();let U=N.attributes,z=L.getAttributes(),B=C.defaultAttributeValues;for(let K in z){let W=z[K];if(W.location>=0){let Y=U[K];if(Y===void 0&&(K==="instanceMatrix"&&R.instanceMatrix&&(Y=R.instanceMatrix),K==="instanceColor"&&R.instanceColor&&(Y=R.instanceColor)),Y!==void 0){let tt=Y.normalized,gt=Y.itemSize,It=t.get(Y);if(It===void 0)continue;let X=It.buffer,it=It.type,_t=It.bytesPerElement,Et=it===i.INT||it===i.UNSIGNED_INT||Y.gpuType===us;if(Y.isInterleavedBufferAttribute){let pt=Y.data,Ut=pt.isInterleavedBuffer===!0?pt.stride:pt.itemSize,ye=Y.offset;if(pt.isInstancedInterleavedBuffer||pt.isInstancedBufferAttribute){for(let Nt=0;Nt<W.locationSize;Nt++)b(W.location+Nt,pt.meshPerAttribute);R.isInstancedMesh!==!0&&N._maxInstanceCount===void 0&&(N._maxInstanceCount=pt.meshPerAttribute*pt.count)}else for(let Nt=0;Nt<W.locationSize;Nt++)g(W.location+Nt);i.bindBuffer(i.ARRAY_BUFFER,X);for(let Nt=0;Nt<W.locationSize;Nt++)w(W.location+Nt,gt/W.locationSize,it,tt,Ut*_t,(ye+gt/W.locationSize*Nt)*_t,Et)}else{if(Y.isInstancedBufferAttribute){for(let pt=0;pt<W.locationSize;pt++)b(W.location+pt,Y.meshPerAttribute);R.isInstancedMesh!==!0&&N._maxInstanceCount===void 0&&(N._maxInstanceCount=Y.meshPerAttribute*Y.count)}else for(let pt=0;pt<W.locationSize;pt++)g(W.location+pt);i.bindBuffer(i.ARRAY_BUFFER,X);for(let pt=0;pt<W.locationSize;pt++)w(W.location+pt,gt/W.locationSize,it,tt,gt*_t,gt/W.locationSize*pt*_t,Et)}}else if(B!==void 0){let tt=B[K];if(tt!==void 0)switch(tt.length){case 2:i.vertexAttrib2fv(W.location,tt);break;case 3:i.vertexAttrib3fv(W.location,tt);break;case 4:i.vertexAttrib4fv(W.location,tt);break;default:i.vertexAttrib1fv(W.location,tt)}}}}v()}function _(){E();for(let R in n){let C=n[R];for(let L in C){let N=C[L];for(let U in N){let z=N[U];for(let B in z)h(z[B].object),delete z[B];delete N[U]}}delete n[R]}}function M(R){if(n[R.id]===void 0)return;let C=n[R.id];for(let L in C){let N=C[L];for(let U in N){let z=N[U];for(let B in z)h(z[B].object),delete z[B];delete N[U]}}delete n[R.id]}function x(R){for(let C in n){let L=n[C];for(let N in L){let U=L[N];if(U[R.id]===void 0)continue;let z=U[R.id];for(let B in z)h(z[B].object),delete z[B];delete U[R.id]}}}function S(R){for(let C in n){let L=n[C],N=R.isInstancedMesh===!0?R.id:0,U=L[N];if(U!==void 0){for(let z in U){let B=U[z];for(let K in B)h(B[K].object),delete B[K];delete U[z]}delete L[N],Object.keys(L).length===0&&delete n[C]}}}function E(){A(),r=!0,s!==a&&(s=a,l(s.object))}function A(){a.geometry=null,a.program=null,a.wireframe=!1}return{setup:o,reset:E,resetDefaultState:A,dispose:_,releaseStatesOfGeometry:M,releaseStatesOfObject:S,releaseStatesOfProgram:x,initAttributes:y,enableAttribute:g,disableUnusedAttributes:v}}function Z_(i,t,e){let n;function a(c){n=c}function s(c,l){i.drawArrays(n,c,l),e.update(l,n,1)}function r(c,l,h){h!==0&&(i.drawArraysInstanced(n,c,l,h),e.update(l,n,h))}function o(c,l,h){if(h===0)return;t.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,c,0,l,0,h);let d=0;for(let f=0;f<h;f++)d+=l[f];e.update(d,n,1)}this.setMode=a,this.render=s,this.renderInstances=r,this.renderMultiDraw=o}function $_(i,t,e,n){let a;function s(){if(a!==void 0)return a;if(t.has("EXT_texture_filter_anisotropic")===!0){let x=t.get("EXT_texture_filter_anisotropic");a=i.getParameter(x.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else a=0;return a}function r(x){return!(x!==mn&&n.convert(x)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(x){let S=x===Zn&&(t.has("EXT_color_buffer_half_float")||t.has("EXT_color_buffer_float"));return!(x!==en&&x!==pn&&!S&&n.convert(x)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function c(x){if(x==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";x="mediump"}return x==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=e.precision!==void 0?e.precision:"highp",h=c(l);h!==l&&(Rt("WebGLRenderer:",l,"not supported, using",h,"instead."),l=h);let u=e.reversedDepthBuffer===!0&&t.has("EXT_clip_control"),d=e.logarithmicDepthBuffer===!0&&u===!1;e.reversedDepthBuffer===!0&&u===!1&&Rt("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),e.logarithmicDepthBuffer===!0&&u===!0&&Rt("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let f=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),m=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),y=i.getParameter(i.MAX_TEXTURE_SIZE),g=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),b=i.getParameter(i.MAX_VERTEX_ATTRIBS),v=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),w=i.getParameter(i.MAX_VARYING_VECTORS),p=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),_=i.getParameter(i.MAX_SAMPLES),M=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:s,getMaxPrecision:c,textureFormatReadable:r,textureTypeReadable:o,precision:l,logarithmicDepthBuffer:d,reversedDepthBuffer:u,maxTextures:f,maxVertexTextures:m,maxTextureSize:y,maxCubemapSize:g,maxAttributes:b,maxVertexUniforms:v,maxVaryings:w,maxFragmentUniforms:p,maxSamples:_,samples:M}}function Q_(i){let t=this,e=null,n=0,a=!1,s=!1,r=new hn,o=new Dt,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(u,d){let f=u.length!==0||d||n!==0||a;return a=d,n=u.length,f},this.beginShadows=function(){s=!0,h(null)},this.endShadows=function(){s=!1},this.setGlobalState=function(u,d){e=h(u,d,0)},this.setState=function(u,d,f){let m=u.clippingPlanes,y=u.clipIntersection,g=u.clipShadows,b=i.get(u);if(!a||m===null||m.length===0||s&&!g)s?h(null):l();else{let v=s?0:n,w=v*4,p=b.clippingState||null;c.value=p,p=h(m,d,w,f);for(let _=0;_!==w;++_)p[_]=e[_];b.clippingState=p,this.numIntersection=y?this.numPlanes:0,this.numPlanes+=v}};function l(){c.value!==e&&(c.value=e,c.needsUpdate=n>0),t.numPlanes=n,t.numIntersection=0}function h(u,d,f,m){let y=u!==null?u.length:0,g=null;if(y!==0){if(g=c.value,m!==!0||g===null){let b=f+y*4,v=d.matrixWorldInverse;o.getNormalMatrix(v),(g===null||g.length<b)&&(g=new Float32Array(b));for(let w=0,p=f;w!==y;++w,p+=4)r.copy(u[w]).applyMatrix4(v,o),r.normal.toArray(g,p),g[p+3]=r.constant}c.value=g,c.needsUpdate=!0}return t.numPlanes=y,t.numIntersection=0,g}}function Vp(i,t,e){return new Xr(i,{minFilter:Pi,generateMipmaps:t,type:Zn,colorSpace:er,depthBuffer:e})}function qr(i,t,e){return new Bn({name:i,uniforms:t,vertexShader:Ht.cube_vert,fragmentShader:e,side:Ge,blending:va,depthTest:!1,depthWrite:!1})}function sv(){return qr("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${lm}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function rv(){return qr("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:hm}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function ov(){return qr("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${ev}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function Hp(){return qr("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function Gp(){return qr("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function cv(i){let t=new WeakMap,e=new WeakMap,n=null;function a(d,f=!1){return d==null?null:f?r(d):s(d)}function s(d){if(d&&d.isTexture){let f=d.mapping;if(f===Rc||f===Cc)if(t.has(d)){let m=t.get(d).texture;return o(m,d.mapping)}else{let m=d.image;if(m&&m.height>0){let y=new Xr(m.height);return y.fromEquirectangularTexture(i,d),t.set(d,y),d.addEventListener("dispose",l),o(y.texture,d.mapping)}else return null}}return d}function r(d){if(d&&d.isTexture&&d.isPMREMTexture!==!0){let f=d.mapping,m=f===Rc||f===Cc,y=f===Sa||f===ds;if(m||y){let g=e.get(d),b=g!==void 0?g.texture.pmremVersion:0;if(d.isRenderTargetTexture&&d.pmremVersion!==b)return n===null&&(n=new pl(i)),g=m?n.fromEquirectangular(d,g):n.fromCubemap(d,g),g.texture.pmremVersion=d.pmremVersion,e.set(d,g),g.texture;if(g!==void 0)return g.texture;{let v=d.image;return m&&v&&v.height>0||y&&v&&c(v)?(n===null&&(n=new pl(i)),g=m?n.fromEquirectangular(d):n.fromCubemap(d),g.texture.pmremVersion=d.pmremVersion,e.set(d,g),d.addEventListener("dispose",h),g.texture):null}}}return d}function o(d,f){return f===Rc?d.mapping=Sa:f===Cc&&(d.mapping=ds),d}function c(d){let f=0,m=6;for(let y=0;y<m;y++)d[y]!==void 0&&f++;return f===m}function l(d){let f=d.target;f.removeEventListener("dispose",l);let m=t.get(f);m!==void 0&&(t.delete(f),m.dispose())}function h(d){let f=d.target;f.removeEventListener("dispose",h);let m=e.get(f);m!==void 0&&(e.delete(f),m.dispose())}function u(){t=new WeakMap,e=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:a,dispose:u}}function lv(i){let t={};function e(n){if(t[n]!==void 0)return t[n];let a=i.getExtension(n);return t[n]=a,a}return{has:function(n){return e(n)!==null},init:function(){e("EXT_color_buffer_float"),e("WEBGL_clip_cull_distance"),e("OES_texture_float_linear"),e("EXT_color_buffer_half_float"),e("WEBGL_multisampled_render_to_texture"),e("WEBGL_render_shared_exponent")},get:function(n){let a=e(n);return a===null&&Zs("WebGLRenderer: "+n+" extension not supported."),a}}}function hv(i,t,e,n){let a={},s=new WeakMap,r=new FinalizationRegistry(m=>delete a[m]);function o(m){c(m.target)}function c(m){m.index!==null&&t.remove(m.index);for(let g in m.attributes)t.remove(m.attributes[g]);m.removeEventListener("dispose",o),delete a[m.id],r.unregister(m);let y=s.get(m);y&&(t.remove(y),s.delete(m)),n.releaseStatesOfGeometry(m),m.isInstancedBufferGeometry===!0&&delete m._maxInstanceCount,e.memory.geometries--}function l(m,y){return a[y.id]!==void 0||(y.addEventListener("dispose",o),a[y.id]=new WeakRef(y),r.register(y,y.id,y),e.memory.geometries++),y}function h(m){let y=m.attributes;for(let g in y)t.update(y[g],i.ARRAY_BUFFER)}function u(m){let y=m.index,g=m.attributes.position,b=0;if(g===void 0)return;let v=y!==null?y.array.length:g.array.length/3-1,w=g.count>=65535?cr:or,p=new w(Math.ceil(v/3)*6,1),_=p.array;if(y!==null){let x=y.array;b=y.version;for(let S=0,E=0;S<v;S+=3){let A=x[S+0],R=x[S+1],C=x[S+2];_[E++]=A,_[E++]=R,_[E++]=R,_[E++]=C,_[E++]=C,_[E++]=A}}else{b=g.version;for(let x=0,S=0;x<v;x+=3){let E=x+0,A=x+1,R=x+2;_[S++]=E,_[S++]=A,_[S++]=A,_[S++]=R,_[S++]=R,_[S++]=E}}p.version=b;let M=s.get(m);M&&t.remove(M),s.set(m,p)}function d(m){let y=s.get(m);if(y){let g=m.index;g!==null&&y.version<g.version&&u(m)}else u(m);return s.get(m)}function f(){for(let m in a){let y=a[m].deref();y!==void 0&&c(y)}}return{get:l,update:h,getWireframeAttribute:d,dispose:f}}function dv(i,t,e){let n;function a(u){n=u}let s,r;function o(u){s=u.type,r=u.bytesPerElement}function c(u,d){i.drawElements(n,d,s,u*r),e.update(d,n,1)}function l(u,d,f){f!==0&&(i.drawElementsInstanced(n,d,s,u*r,f),e.update(d,n,f))}function h(u,d,f){if(f===0)return;t.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,d,0,s,u,0,f);let y=0;for(let g=0;g<f;g++)y+=d[g];e.update(y,n,1)}this.setMode=a,this.setIndex=o,this.render=c,this.renderInstances=l,this.renderMultiDraw=h}function uv(i){let t={geometries:0,textures:0},e={frame:0,calls:0,triangles:0,points:0,lines:0};function n(s,r,o){switch(e.calls++,r){case i.TRIANGLES:e.triangles+=o*(s/3);break;case i.LINES:e.lines+=o*(s/2);break;case i.LINE_STRIP:e.lines+=o*(s-1);break;case i.LINE_LOOP:e.lines+=o*s;break;case i.POINTS:e.points+=o*s;break;default:Lt("WebGLInfo: Unknown draw mode:",r);break}}function a(){e.calls=0,e.triangles=0,e.points=0,e.lines=0}return{memory:t,render:e,programs:null,autoReset:!0,reset:a,update:n}}function fv(i,t,e){let n=new WeakMap,a=new $t;function s(r,o,c){let l=r.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,u=h!==void 0?h.length:0,d=n.get(o);if(d===void 0||d.count!==u){let E=function(){x.dispose(),n.delete(o),o.removeEventListener("dispose",E)};d!==void 0&&d.texture.dispose();let f=o.morphAttributes.position!==void 0,m=o.morphAttributes.normal!==void 0,y=o.morphAttributes.color!==void 0,g=o.morphAttributes.position||[],b=o.morphAttributes.normal||[],v=o.morphAttributes.color||[],w=0;f===!0&&(w=1),m===!0&&(w=2),y===!0&&(w=3);let p=o.attributes.position.count*w,_=1;p>t.maxTextureSize&&(_=Math.ceil(p/t.maxTextureSize),p=t.maxTextureSize);let M=new Float32Array(p*_*4*u),x=new sr(M,p,_,u);x.type=pn,x.needsUpdate=!0;let S=w*4;for(let A=0;A<u;A++){let R=g[A],C=b[A],L=v[A],N=p*_*4*A;for(let U=0;U<R.count;U++){let z=U*S;f===!0&&(a.fromBufferAttribute(R,U),M[N+z+0]=a.x,M[N+z+1]=a.y,M[N+z+2]=a.z,M[N+z+3]=0),m===!0&&(a.fromBufferAttribute(C,U),M[N+z+4]=a.x,M[N+z+5]=a.y,M[N+z+6]=a.z,M[N+z+7]=0),y===!0&&(a.fromBufferAttribute(L,U),M[N+z+8]=a.x,M[N+z+9]=a.y,M[N+z+10]=a.z,M[N+z+11]=L.itemSize===4?a.w:1)}}d={count:u,texture:x,size:new Ct(p,_)},n.set(o,d),o.addEventListener("dispose",E)}if(r.isInstancedMesh===!0&&r.morphTexture!==null)c.getUniforms().setValue(i,"morphTexture",r.morphTexture,e);else{let f=0;for(let y=0;y<l.length;y++)f+=l[y];let m=o.morphTargetsRelative?1:1-f;c.getUniforms().setValue(i,"morphTargetBaseInfluence",m),c.getUniforms().setValue(i,"morphTargetInfluences",l)}c.getUniforms().setValue(i,"morphTargetsTexture",d.texture,e),c.getUniforms().setValue(i,"morphTargetsTextureSize",d.size)}return{update:s}}function pv(i,t,e,n,a){let s=new WeakMap;function r(l){let h=a.render.frame,u=l.geometry,d=t.get(l,u);if(s.get(d)!==h&&(t.update(d),s.set(d,h)),l.isInstancedMesh&&(l.hasEventListener("dispose",c)===!1&&l.addEventListener("dispose",c),s.get(l)!==h&&(e.update(l.instanceMatrix,i.ARRAY_BUFFER),l.instanceColor!==null&&e.update(l.instanceColor,i.ARRAY_BUFFER),s.set(l,h))),l.isSkinnedMesh){let f=l.skeleton;s.get(f)!==h&&(f.update(),s.set(f,h))}return d}function o(){s=new WeakMap}function c(l){let h=l.target;h.removeEventListener("dispose",c),n.releaseStatesOfObject(h),e.remove(h.instanceMatrix),h.instanceColor!==null&&e.remove(h.instanceColor)}return{update:r,dispose:o}}function gv(i,t,e,n,a,s){let r=new In(t,e,{type:i,depthBuffer:a,stencilBuffer:s,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),o=null,c=null,l=null,h=new Ae;h.setAttribute("position",new re([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new re([0,2,0,0,2,0],2));let u=new dc({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),d=new tn(h,u),f=new Ar(-1,1,1,-1,0,1),m=null,y=null,g=!1,b,v=null,w=[],p=!1;this.setSize=function(_,M){r.setSize(_,M),o!==null&&o.setSize(_,M),c!==null&&c.setSize(_,M);for(let x=0;x<w.length;x++){let S=w[x];S.setSize&&S.setSize(_,M)}},this.setEffects=function(_){w=_,p=w.length>0&&w[0].isRenderPass===!0;let M=r.width,x=r.height;w.length>0&&o===null&&(o=new In(M,x,{type:Zn,depthBuffer:!1,stencilBuffer:!1}),c=new In(M,x,{type:Zn,depthBuffer:!1,stencilBuffer:!1}));let S=a===!0&&w.some(E=>E.needsDepthTexture===!0);S!==(r.depthTexture!==null)&&(S===!0&&l===null&&(l=new Ni(M,x),s===!0&&(l.format=Li,l.type=wa)),r.dispose(),r.depthTexture=S?l:null,r.resolveDepthBuffer=S,r.storeMultisampledDepthBuffer=S);for(let E=0;E<w.length;E++){let A=w[E];A.setSize&&A.setSize(M,x),S&&A.needsDepthTexture===!0&&A.setDepthTexture&&A.setDepthTexture(l)}},this.begin=function(_,M){if(g||_.toneMapping===li&&w.length===0)return!1;if(v=M,M!==null){let x=M.width,S=M.height;(r.width!==x||r.height!==S)&&this.setSize(x,S)}return p===!1&&_.setRenderTarget(r),b=_.toneMapping,_.toneMapping=li,!0},this.hasRenderPass=function(){return p},this.end=function(_,M){_.toneMapping=b,g=!0;let x=r,S=o;for(let E=0;E<w.length;E++){let A=w[E];A.enabled!==!1&&(A.render(_,S,x,M),A.needsSwap!==!1&&(x=S,S=S===o?c:o))}if(m!==_.outputColorSpace||y!==_.toneMapping){m=_.outputColorSpace,y=_.toneMapping,u.defines={},Gt.getTransfer(m)===ie&&(u.defines.SRGB_TRANSFER="");let E=mv[y];E&&(u.defines[E]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=x.texture,_.setRenderTarget(v),_.render(d,f),v=null,g=!1},this.isCompositing=function(){return g},this.dispose=function(){r.dispose(),o!==null&&o.dispose(),c!==null&&c.dispose(),h.dispose(),u.dispose()}}function gs(i,t,e){let n=i[0];if(n<=0||n>0)return i;let a=t*e,s=Wp[a];if(s===void 0&&(s=new Float32Array(a),Wp[a]=s),t!==0){n.toArray(s,0);for(let r=1,o=0;r!==t;++r)o+=e,i[r].toArray(s,o)}return s}function Ce(i,t){if(i.length!==t.length)return!1;for(let e=0,n=i.length;e<n;e++)if(i[e]!==t[e])return!1;return!0}function Ne(i,t){for(let e=0,n=t.length;e<n;e++)i[e]=t[e]}function gl(i,t){let e=jp[t];e===void 0&&(e=new Int32Array(t),jp[t]=e);for(let n=0;n!==t;++n)e[n]=i.allocateTextureUnit();return e}function bv(i,t){let e=this.cache;e[0]!==t&&(i.uniform1f(this.addr,t),e[0]=t)}function xv(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2f(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Ce(e,t))return;i.uniform2fv(this.addr,t),Ne(e,t)}}function yv(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3f(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else if(t.r!==void 0)(e[0]!==t.r||e[1]!==t.g||e[2]!==t.b)&&(i.uniform3f(this.addr,t.r,t.g,t.b),e[0]=t.r,e[1]=t.g,e[2]=t.b);else{if(Ce(e,t))return;i.uniform3fv(this.addr,t),Ne(e,t)}}function _v(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4f(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Ce(e,t))return;i.uniform4fv(this.addr,t),Ne(e,t)}}function vv(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Ce(e,t))return;i.uniformMatrix2fv(this.addr,!1,t),Ne(e,t)}else{if(Ce(e,n))return;Yp.set(n),i.uniformMatrix2fv(this.addr,!1,Yp),Ne(e,n)}}function Mv(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Ce(e,t))return;i.uniformMatrix3fv(this.addr,!1,t),Ne(e,t)}else{if(Ce(e,n))return;qp.set(n),i.uniformMatrix3fv(this.addr,!1,qp),Ne(e,n)}}function Sv(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Ce(e,t))return;i.uniformMatrix4fv(this.addr,!1,t),Ne(e,t)}else{if(Ce(e,n))return;Xp.set(n),i.uniformMatrix4fv(this.addr,!1,Xp),Ne(e,n)}}function wv(i,t){let e=this.cache;e[0]!==t&&(i.uniform1i(this.addr,t),e[0]=t)}function Av(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2i(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Ce(e,t))return;i.uniform2iv(this.addr,t),Ne(e,t)}}function Ev(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3i(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Ce(e,t))return;i.uniform3iv(this.addr,t),Ne(e,t)}}function Tv(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4i(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Ce(e,t))return;i.uniform4iv(this.addr,t),Ne(e,t)}}function Iv(i,t){let e=this.cache;e[0]!==t&&(i.uniform1ui(this.addr,t),e[0]=t)}function Rv(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2ui(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Ce(e,t))return;i.uniform2uiv(this.addr,t),Ne(e,t)}}function Cv(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3ui(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Ce(e,t))return;i.uniform3uiv(this.addr,t),Ne(e,t)}}function Nv(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4ui(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Ce(e,t))return;i.uniform4uiv(this.addr,t),Ne(e,t)}}function bl(i){return i.version===0&&(i.compareFunction=pd,i.needsUpdate=!0),i}function Pv(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a);let s;this.type===i.SAMPLER_2D_SHADOW?s=bl(um):s=dm,e.setTexture2D(t||s,a)}function Lv(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a),e.setTexture3D(t||mm,a)}function Dv(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a);let s;this.type===i.SAMPLER_CUBE_SHADOW?s=bl(fm):s=gm,e.setTextureCube(t||s,a)}function Uv(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a),e.setTexture2DArray(t||pm,a)}function Ov(i){switch(i){case 5126:return bv;case 35664:return xv;case 35665:return yv;case 35666:return _v;case 35674:return vv;case 35675:return Mv;case 35676:return Sv;case 5124:case 35670:return wv;case 35667:case 35671:return Av;case 35668:case 35672:return Ev;case 35669:case 35673:return Tv;case 5125:return Iv;case 36294:return Rv;case 36295:return Cv;case 36296:return Nv;case 35678:case 36198:case 36298:case 36306:case 35682:return Pv;case 35679:case 36299:case 36307:return Lv;case 35680:case 36300:case 36308:case 36293:return Dv;case 36289:case 36303:case 36311:case 36292:return Uv}}function Fv(i,t){i.uniform1fv(this.addr,t)}function Bv(i,t){let e=gs(t,this.size,2);i.uniform2fv(this.addr,e)}function kv(i,t){let e=gs(t,this.size,3);i.uniform3fv(this.addr,e)}function zv(i,t){let e=gs(t,this.size,4);i.uniform4fv(this.addr,e)}function Vv(i,t){let e=gs(t,this.size,4);i.uniformMatrix2fv(this.addr,!1,e)}function Hv(i,t){let e=gs(t,this.size,9);i.uniformMatrix3fv(this.addr,!1,e)}function Gv(i,t){let e=gs(t,this.size,16);i.uniformMatrix4fv(this.addr,!1,e)}function Wv(i,t){i.uniform1iv(this.addr,t)}function jv(i,t){i.uniform2iv(this.addr,t)}function Xv(i,t){i.uniform3iv(this.addr,t)}function qv(i,t){i.uniform4iv(this.addr,t)}function Yv(i,t){i.uniform1uiv(this.addr,t)}function Jv(i,t){i.uniform2uiv(this.addr,t)}function Kv(i,t){i.uniform3uiv(this.addr,t)}function Zv(i,t){i.uniform4uiv(this.addr,t)}function $v(i,t,e){let n=this.cache,a=t.length,s=gl(e,a);Ce(n,s)||(i.uniform1iv(this.addr,s),Ne(n,s));let r;this.type===i.SAMPLER_2D_SHADOW?r=bl(um):r=dm;for(let o=0;o!==a;++o)e.setTexture2D(t[o]||r,s[o])}function Qv(i,t,e){let n=this.cache,a=t.length,s=gl(e,a);Ce(n,s)||(i.uniform1iv(this.addr,s),Ne(n,s));for(let r=0;r!==a;++r)e.setTexture3D(t[r]||mm,s[r])}function tM(i,t,e){let n=this.cache,a=t.length,s=gl(e,a);Ce(n,s)||(i.uniform1iv(this.addr,s),Ne(n,s));let r;this.type===i.SAMPLER_CUBE_SHADOW?r=bl(fm):r=gm;for(let o=0;o!==a;++o)e.setTextureCube(t[o]||r,s[o])}function eM(i,t,e){let n=this.cache,a=t.length,s=gl(e,a);Ce(n,s)||(i.uniform1iv(this.addr,s),Ne(n,s));for(let r=0;r!==a;++r)e.setTexture2DArray(t[r]||pm,s[r])}function nM(i){switch(i){case 5126:return Fv;case 35664:return Bv;case 35665:return kv;case 35666:return zv;case 35674:return Vv;case 35675:return Hv;case 35676:return Gv;case 5124:case 35670:return Wv;case 35667:case 35671:return jv;case 35668:case 35672:return Xv;case 35669:case 35673:return qv;case 5125:return Yv;case 36294:return Jv;case 36295:return Kv;case 36296:return Zv;case 35678:case 36198:case 36298:case 36306:case 35682:return $v;case 35679:case 36299:case 36307:return Qv;case 35680:case 36300:case 36308:case 36293:return tM;case 36289:case 36303:case 36311:case 36292:return eM}}function Jp(i,t){i.seq.push(t),i.map[t.id]=t}function iM(i,t,e){let n=i.name,a=n.length;for(Nd.lastIndex=0;;){let s=Nd.exec(n),r=Nd.lastIndex,o=s[1],c=s[2]==="]",l=s[3];if(c&&(o=o|0),l===void 0||l==="["&&r+2===a){Jp(e,l===void 0?new Ld(o,i,t):new Dd(o,i,t));break}else{let u=e.map[o];u===void 0&&(u=new Ud(o),Jp(e,u)),e=u}}}function Kp(i,t,e){let n=i.createShader(t);return i.shaderSource(n,e),i.compileShader(n),n}function rM(i,t){let e=i.split(`
`),n=[],a=Math.max(t-6,0),s=Math.min(t+6,e.length);for(let r=a;r<s;r++){let o=r+1;n.push(`${o===t?">":" "} ${o}: ${e[r]}`)}return n.join(`
`)}function oM(i){Gt._getMatrix(Zp,Gt.workingColorSpace,i);let t=`mat3( ${Zp.elements.map(e=>e.toFixed(4))} )`;switch(Gt.getTransfer(i)){case nr:return[t,"LinearTransferOETF"];case ie:return[t,"sRGBTransferOETF"];default:return Rt("WebGLProgram: Unsupported color space: ",i),[t,"LinearTransferOETF"]}}function $p(i,t,e){let n=i.getShaderParameter(t,i.COMPILE_STATUS),s=(i.getShaderInfoLog(t)||"").trim();if(n&&s==="")return"";let r=/ERROR: 0:(\d+)/.exec(s);if(r){let o=parseInt(r[1]);return e.toUpperCase()+`

`+s+`

`+rM(i.getShaderSource(t),o)}else return s}function cM(i,t){let e=oM(t);return[`vec4 ${i}( vec4 value ) {`,`	return ${e[1]}( vec4( ${e[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}function hM(i,t){let e=lM[t];return e===void 0?(Rt("WebGLProgram: Unsupported toneMapping:",t),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+e+"ToneMapping( color ); }"}function dM(){Gt.getLuminanceCoefficients(fl);let i=fl.x.toFixed(4),t=fl.y.toFixed(4),e=fl.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${t}, ${e} );`,"	return dot( weights, rgb );","}"].join(`
`)}function uM(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(jr).join(`
`)}function fM(i){let t=[];for(let e in i){let n=i[e];n!==!1&&t.push("#define "+e+" "+n)}return t.join(`
`)}function pM(i,t){let e={},n=i.getProgramParameter(t,i.ACTIVE_ATTRIBUTES);for(let a=0;a<n;a++){let s=i.getActiveAttrib(t,a),r=s.name,o=1;s.type===i.FLOAT_MAT2&&(o=2),s.type===i.FLOAT_MAT3&&(o=3),s.type===i.FLOAT_MAT4&&(o=4),e[r]={type:s.type,location:i.getAttribLocation(t,r),locationSize:o}}return e}function jr(i){return i!==""}function Qp(i,t){let e=t.numSpotLightShadows+t.numSpotLightMaps-t.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,t.numSunLights).replace(/NUM_DIR_LIGHTS/g,t.numDirLights).replace(/NUM_SPOT_LIGHTS/g,t.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,t.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,e).replace(/NUM_RECT_AREA_LIGHTS/g,t.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,t.numPointLights).replace(/NUM_HEMI_LIGHTS/g,t.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,t.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,t.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,t.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,t.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,t.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,t.numLightProbeGrids)}function tm(i,t){return i.replace(/NUM_CLIPPING_PLANES/g,t.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,t.numClippingPlanes-t.numClipIntersection)}function Od(i){return i.replace(mM,gM)}function gM(i,t){let e=Ht[t];if(e===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+t+">");return Od(e)}function em(i){return i.replace(bM,xM)}function xM(i,t,e,n){let a="";for(let s=parseInt(t);s<parseInt(e);s++)a+=n.replace(/\[\s*i\s*\]/g,"[ "+s+" ]").replace(/UNROLLED_LOOP_INDEX/g,s);return a}function nm(i){let t=`precision ${i.precision} float;
	precision ${i.precision} int;
	precision ${i.precision} sampler2D;
	precision ${i.precision} samplerCube;
	precision ${i.precision} sampler3D;
	precision ${i.precision} sampler2DArray;
	precision ${i.precision} sampler2DShadow;
	precision ${i.precision} samplerCubeShadow;
	precision ${i.precision} sampler2DArrayShadow;
	precision ${i.precision} isampler2D;
	precision ${i.precision} isampler3D;
	precision ${i.precision} isamplerCube;
	precision ${i.precision} isampler2DArray;
	precision ${i.precision} usampler2D;
	precision ${i.precision} usampler3D;
	precision ${i.precision} usamplerCube;
	precision ${i.precision} usampler2DArray;
	`;return i.precision==="highp"?t+=`
#define HIGH_PRECISION`:i.precision==="mediump"?t+=`
#define MEDIUM_PRECISION`:i.precision==="lowp"&&(t+=`
#define LOW_PRECISION`),t}function _M(i){return yM[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}function MM(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":vM[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}function wM(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":SM[i.combine]||"ENVMAP_BLENDING_NONE"}function AM(i,t,e,n){let a=i.getContext(),s=e.defines,r=e.vertexShader,o=e.fragmentShader,c=_M(e),l=e.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=MM(e),u=wM(e),d=uM(e),f=fM(s),m=a.createProgram(),y,g,b=e.glslVersion?"#version "+e.glslVersion+`
`:"";e.isRawShaderMaterial?(y=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f].filter(jr).join(`
`),y.length>0&&(y+=`
`),g=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f].filter(jr).join(`
`),g.length>0&&(g+=`
`)):(y=[nm(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f,e.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",e.batching?"#define USE_BATCHING":"",e.batchingColor?"#define USE_BATCHING_COLOR":"",e.instancing?"#define USE_INSTANCING":"",e.instancingColor?"#define USE_INSTANCING_COLOR":"",e.instancingMorph?"#define USE_INSTANCING_MORPH":"",e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.map?"#define USE_MAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+h:"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.displacementMap?"#define USE_DISPLACEMENTMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.mapUv?"#define MAP_UV "+e.mapUv:"",e.alphaMapUv?"#define ALPHAMAP_UV "+e.alphaMapUv:"",e.lightMapUv?"#define LIGHTMAP_UV "+e.lightMapUv:"",e.aoMapUv?"#define AOMAP_UV "+e.aoMapUv:"",e.emissiveMapUv?"#define EMISSIVEMAP_UV "+e.emissiveMapUv:"",e.bumpMapUv?"#define BUMPMAP_UV "+e.bumpMapUv:"",e.normalMapUv?"#define NORMALMAP_UV "+e.normalMapUv:"",e.displacementMapUv?"#define DISPLACEMENTMAP_UV "+e.displacementMapUv:"",e.metalnessMapUv?"#define METALNESSMAP_UV "+e.metalnessMapUv:"",e.roughnessMapUv?"#define ROUGHNESSMAP_UV "+e.roughnessMapUv:"",e.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+e.anisotropyMapUv:"",e.clearcoatMapUv?"#define CLEARCOATMAP_UV "+e.clearcoatMapUv:"",e.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+e.clearcoatNormalMapUv:"",e.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+e.clearcoatRoughnessMapUv:"",e.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+e.diffuseRoughnessMapUv:"",e.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+e.iridescenceMapUv:"",e.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+e.iridescenceThicknessMapUv:"",e.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+e.sheenColorMapUv:"",e.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+e.sheenRoughnessMapUv:"",e.specularMapUv?"#define SPECULARMAP_UV "+e.specularMapUv:"",e.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+e.specularColorMapUv:"",e.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+e.specularIntensityMapUv:"",e.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+e.transmissionMapUv:"",e.thicknessMapUv?"#define THICKNESSMAP_UV "+e.thicknessMapUv:"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexNormals?"#define HAS_NORMAL":"",e.vertexColors?"#define USE_COLOR":"",e.vertexAlphas?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.flatShading?"#define FLAT_SHADED":"",e.skinning?"#define USE_SKINNING":"",e.morphTargets?"#define USE_MORPHTARGETS":"",e.morphNormals&&e.flatShading===!1?"#define USE_MORPHNORMALS":"",e.morphColors?"#define USE_MORPHCOLORS":"",e.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+e.morphTextureStride:"",e.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+e.morphTargetsCount:"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.sizeAttenuation?"#define USE_SIZEATTENUATION":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(jr).join(`
`),g=[nm(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f,e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",e.map?"#define USE_MAP":"",e.matcap?"#define USE_MATCAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+l:"",e.envMap?"#define "+h:"",e.envMap?"#define "+u:"",e.envMapPMREM?"#define ENVMAP_MAX_LOD "+e.envMapMaxLod+".0":"",e.envMapPMREM?"#define ENVMAP_SIZE "+e.envMapSize+".0":"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoat?"#define USE_CLEARCOAT":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.dispersion?"#define USE_DISPERSION":"",e.retroreflection?"#define USE_RETROREFLECTION":"",e.iridescence?"#define USE_IRIDESCENCE":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaTest?"#define USE_ALPHATEST":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.sheen?"#define USE_SHEEN":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexColors||e.instancingColor?"#define USE_COLOR":"",e.vertexAlphas||e.batchingColor?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.gradientMap?"#define USE_GRADIENTMAP":"",e.flatShading?"#define FLAT_SHADED":"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",e.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",e.toneMapping!==li?"#define TONE_MAPPING":"",e.toneMapping!==li?Ht.tonemapping_pars_fragment:"",e.toneMapping!==li?hM("toneMapping",e.toneMapping):"",e.dithering?"#define DITHERING":"",e.opaque?"#define OPAQUE":"",Ht.colorspace_pars_fragment,cM("linearToOutputTexel",e.outputColorSpace),dM(),e.useDepthPacking?"#define DEPTH_PACKING "+e.depthPacking:"",`
`].filter(jr).join(`
`)),r=Od(r),r=Qp(r,e),r=tm(r,e),o=Od(o),o=Qp(o,e),o=tm(o,e),r=em(r),o=em(o),e.isRawShaderMaterial!==!0&&(b=`#version 300 es
`,y=[d,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+y,g=["#define varying in",e.glslVersion===gd?"":"layout(location = 0) out highp vec4 pc_fragColor;",e.glslVersion===gd?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+g);let v=b+y+r,w=b+g+o,p=Kp(a,a.VERTEX_SHADER,v),_=Kp(a,a.FRAGMENT_SHADER,w);a.attachShader(m,p),a.attachShader(m,_),e.index0AttributeName!==void 0?a.bindAttribLocation(m,0,e.index0AttributeName):e.hasPositionAttribute===!0&&a.bindAttribLocation(m,0,"position"),a.linkProgram(m);function M(A){if(i.debug.checkShaderErrors){let R=a.getProgramInfoLog(m)||"",C=a.getShaderInfoLog(p)||"",L=a.getShaderInfoLog(_)||"",N=R.trim(),U=C.trim(),z=L.trim(),B=!0,K=!0;if(a.getProgramParameter(m,a.LINK_STATUS)===!1)if(B=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(a,m,p,_);else{let W=$p(a,p,"vertex"),Y=$p(a,_,"fragment");Lt("WebGLProgram: Shader Error "+a.getError()+" - VALIDATE_STATUS "+a.getProgramParameter(m,a.VALIDATE_STATUS)+`

Material Name: `+A.name+`
Material Type: `+A.type+`

Program Info Log: `+N+`
`+W+`
`+Y)}else N!==""?Rt("WebGLProgram: Program Info Log:",N):(U===""||z==="")&&(K=!1);K&&(A.diagnostics={runnable:B,programLog:N,vertexShader:{log:U,prefix:y},fragmentShader:{log:z,prefix:g}})}a.deleteShader(p),a.deleteShader(_),x=new ms(a,m),S=pM(a,m)}let x;this.getUniforms=function(){return x===void 0&&M(this),x};let S;this.getAttributes=function(){return S===void 0&&M(this),S};let E=e.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return E===!1&&(E=a.getProgramParameter(m,aM)),E},this.destroy=function(){n.releaseStatesOfProgram(this),a.deleteProgram(m),this.program=void 0},this.type=e.shaderType,this.name=e.shaderName,this.id=sM++,this.cacheKey=t,this.usedTimes=1,this.program=m,this.vertexShader=p,this.fragmentShader=_,this}function TM(i){return i===hi||i===Vr||i===Hr}function IM(i,t,e,n,a,s){let r=new es,o=new Fd,c=new Set,l=[],h=new Map,u=n.logarithmicDepthBuffer,d={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function f(x){return c.add(x),x===0?"uv":`uv${x}`}function m(x,S,E,A,R,C){let L=A.fog,N=R.geometry,U=x.isMeshStandardMaterial||x.isMeshLambertMaterial||x.isMeshPhongMaterial?A.environment:null,z=x.isMeshStandardMaterial||x.isMeshLambertMaterial&&!x.envMap||x.isMeshPhongMaterial&&!x.envMap,B=t.get(x.envMap||U,z),K=d[x.type],W=n.precision;x.precision!==null&&(W=n.getMaxPrecision(x.precision),W!==x.precision&&Rt("WebGLProgram.getParameters:",x.precision,"not supported, using",W,"instead."));let Y=N.morphAttributes.position||N.morphAttributes.normal||N.morphAttributes.color,tt=Y!==void 0?Y.length:0,gt=0;N.morphAttributes.position!==void 0&&(gt=1),N.morphAttributes.normal!==void 0&&(gt=2),N.morphAttributes.color!==void 0&&(gt=3);let It,X,it,_t;if(K){let bt=gn[K];It=bt.vertexShader,X=bt.fragmentShader}else{It=x.vertexShader,X=x.fragmentShader;let bt=o.getVertexShaderStage(x),se=o.getFragmentShaderStage(x);o.update(x,bt,se),it=bt.id,_t=se.id}let Et=i.getRenderTarget(),pt=i.state.buffers.depth.getReversed(),Ut=R.isInstancedMesh===!0,ye=R.isBatchedMesh===!0,Nt=!!x.map,Jt=!!x.matcap,ce=!!B,jt=ce&&B.isPMREMTexture===!0,Ve=!!x.aoMap,Ee=!!x.lightMap,yn=!!x.bumpMap&&x.wireframe===!1,ge=!!x.normalMap,ei=!!x.displacementMap,De=!!x.emissiveMap,Pn=!!x.metalnessMap,Ln=!!x.roughnessMap,Dn=x.anisotropy>0,k=x.clearcoat>0,Un=x.diffuseRoughness>0,pe=x.dispersion>0,me=x.retroreflectivity>0,mt=x.iridescence>0,Te=x.sheen>0,Pt=x.transmission>0,Ot=Dn&&!!x.anisotropyMap,P=k&&!!x.clearcoatMap,T=k&&!!x.clearcoatNormalMap,H=k&&!!x.clearcoatRoughnessMap,nt=Un&&!!x.diffuseRoughnessMap,Q=mt&&!!x.iridescenceMap,rt=mt&&!!x.iridescenceThicknessMap,dt=Te&&!!x.sheenColorMap,J=Te&&!!x.sheenRoughnessMap,Z=!!x.specularMap,ct=!!x.specularColorMap,D=!!x.specularIntensityMap,$=Pt&&!!x.transmissionMap,q=Pt&&!!x.thicknessMap,lt=!!x.gradientMap,st=!!x.alphaMap,ot=x.alphaTest>0,At=!!x.alphaHash,Vt=!!x.extensions,at=li;x.toneMapped&&(Et===null||Et.isXRRenderTarget===!0)&&(at=i.toneMapping);let Tt=jt?B.isCompressedCubeTexture?B.image[0].mipmaps:B.mipmaps:null,zt={shaderID:K,shaderType:x.type,shaderName:x.name,vertexShader:It,fragmentShader:X,defines:x.defines,customVertexShaderID:it,customFragmentShaderID:_t,isRawShaderMaterial:x.isRawShaderMaterial===!0,glslVersion:x.glslVersion,precision:W,batching:ye,batchingColor:ye&&R._colorsTexture!==null,instancing:Ut,instancingColor:Ut&&R.instanceColor!==null,instancingMorph:Ut&&R.morphTexture!==null,outputColorSpace:Et===null?i.outputColorSpace:Et.isXRRenderTarget===!0?Et.texture.colorSpace:Gt.workingColorSpace,alphaToCoverage:!!x.alphaToCoverage,map:Nt,matcap:Jt,envMap:ce,envMapMode:ce&&B.mapping,envMapPMREM:jt,envMapMaxLod:jt?Tt.length-1:null,envMapSize:jt?Tt[0].width:null,aoMap:Ve,lightMap:Ee,bumpMap:yn,normalMap:ge,displacementMap:ei,emissiveMap:De,normalMapObjectSpace:ge&&x.normalMapType===Ep,normalMapTangentSpace:ge&&x.normalMapType===hl,packedNormalMap:ge&&x.normalMapType===hl&&TM(x.normalMap.format),metalnessMap:Pn,roughnessMap:Ln,anisotropy:Dn,anisotropyMap:Ot,clearcoat:k,clearcoatMap:P,clearcoatNormalMap:T,clearcoatRoughnessMap:H,diffuseRoughness:Un,diffuseRoughnessMap:nt,dispersion:pe,retroreflection:me,iridescence:mt,iridescenceMap:Q,iridescenceThicknessMap:rt,sheen:Te,sheenColorMap:dt,sheenRoughnessMap:J,specularMap:Z,specularColorMap:ct,specularIntensityMap:D,transmission:Pt,transmissionMap:$,thicknessMap:q,gradientMap:lt,opaque:x.transparent===!1&&x.blending===hs&&x.alphaToCoverage===!1,alphaMap:st,alphaTest:ot,alphaHash:At,combine:x.combine,mapUv:Nt&&f(x.map.channel),aoMapUv:Ve&&f(x.aoMap.channel),lightMapUv:Ee&&f(x.lightMap.channel),bumpMapUv:yn&&f(x.bumpMap.channel),normalMapUv:ge&&f(x.normalMap.channel),displacementMapUv:ei&&f(x.displacementMap.channel),emissiveMapUv:De&&f(x.emissiveMap.channel),metalnessMapUv:Pn&&f(x.metalnessMap.channel),roughnessMapUv:Ln&&f(x.roughnessMap.channel),anisotropyMapUv:Ot&&f(x.anisotropyMap.channel),clearcoatMapUv:P&&f(x.clearcoatMap.channel),clearcoatNormalMapUv:T&&f(x.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:H&&f(x.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:nt&&f(x.diffuseRoughnessMap.channel),iridescenceMapUv:Q&&f(x.iridescenceMap.channel),iridescenceThicknessMapUv:rt&&f(x.iridescenceThicknessMap.channel),sheenColorMapUv:dt&&f(x.sheenColorMap.channel),sheenRoughnessMapUv:J&&f(x.sheenRoughnessMap.channel),specularMapUv:Z&&f(x.specularMap.channel),specularColorMapUv:ct&&f(x.specularColorMap.channel),specularIntensityMapUv:D&&f(x.specularIntensityMap.channel),transmissionMapUv:$&&f(x.transmissionMap.channel),thicknessMapUv:q&&f(x.thicknessMap.channel),alphaMapUv:st&&f(x.alphaMap.channel),vertexTangents:!!N.attributes.tangent&&(ge||Dn),vertexNormals:!!N.attributes.normal,vertexColors:x.vertexColors,vertexAlphas:x.vertexColors===!0&&!!N.attributes.color&&N.attributes.color.itemSize===4,pointsUvs:R.isPoints===!0&&!!N.attributes.uv&&(Nt||st),fog:!!L,useFog:x.fog===!0,fogExp2:!!L&&L.isFogExp2,flatShading:x.wireframe===!1&&(x.flatShading===!0||N.attributes.normal===void 0&&ge===!1&&(x.isMeshLambertMaterial||x.isMeshPhongMaterial||x.isMeshStandardMaterial||x.isMeshPhysicalMaterial)),sizeAttenuation:x.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:pt,skinning:R.isSkinnedMesh===!0,hasPositionAttribute:N.attributes.position!==void 0,morphTargets:N.morphAttributes.position!==void 0,morphNormals:N.morphAttributes.normal!==void 0,morphColors:N.morphAttributes.color!==void 0,morphTargetsCount:tt,morphTextureStride:gt,numSunLights:S.sun.length,numDirLights:S.directional.length,numPointLights:S.point.length,numSpotLights:S.spot.length,numSpotLightMaps:S.spotLightMap.length,numRectAreaLights:S.rectArea.length,numHemiLights:S.hemi.length,numSunLightShadows:S.sunShadowMap.length,numDirLightShadows:S.directionalShadowMap.length,numPointLightShadows:S.pointShadowMap.length,numSpotLightShadows:S.spotShadowMap.length,numSpotLightShadowsWithMaps:S.numSpotLightShadowsWithMaps,numLightProbes:S.numLightProbes,numLightProbeGrids:C.filter(bt=>bt.texture!==null).length,numClippingPlanes:s.numPlanes,numClipIntersection:s.numIntersection,dithering:x.dithering,shadowMapEnabled:i.shadowMap.enabled&&E.length>0,shadowMapType:i.shadowMap.type,toneMapping:at,decodeVideoTexture:Nt&&x.map.isVideoTexture===!0&&Gt.getTransfer(x.map.colorSpace)===ie,decodeVideoTextureEmissive:De&&x.emissiveMap.isVideoTexture===!0&&Gt.getTransfer(x.emissiveMap.colorSpace)===ie,premultipliedAlpha:x.premultipliedAlpha,doubleSided:x.side===kn,flipSided:x.side===Ge,useDepthPacking:x.depthPacking>=0,depthPacking:x.depthPacking||0,index0AttributeName:x.index0AttributeName,extensionClipCullDistance:Vt&&x.extensions.clipCullDistance===!0&&e.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Vt&&x.extensions.multiDraw===!0||ye)&&e.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:e.has("KHR_parallel_shader_compile"),customProgramCacheKey:x.customProgramCacheKey()};return zt.vertexUv1s=c.has(1),zt.vertexUv2s=c.has(2),zt.vertexUv3s=c.has(3),c.clear(),zt}function y(x){let S=[];if(x.shaderID?S.push(x.shaderID):(S.push(x.customVertexShaderID),S.push(x.customFragmentShaderID)),x.defines!==void 0)for(let E in x.defines)S.push(E),S.push(x.defines[E]);return x.isRawShaderMaterial===!1&&(g(S,x),b(S,x),S.push(i.outputColorSpace)),S.push(x.customProgramCacheKey),S.join()}function g(x,S){x.push(S.precision),x.push(S.outputColorSpace),x.push(S.envMapMode),x.push(S.envMapPMREM),x.push(S.envMapMaxLod),x.push(S.envMapSize),x.push(S.mapUv),x.push(S.alphaMapUv),x.push(S.lightMapUv),x.push(S.aoMapUv),x.push(S.bumpMapUv),x.push(S.normalMapUv),x.push(S.displacementMapUv),x.push(S.emissiveMapUv),x.push(S.metalnessMapUv),x.push(S.roughnessMapUv),x.push(S.anisotropyMapUv),x.push(S.clearcoatMapUv),x.push(S.clearcoatNormalMapUv),x.push(S.clearcoatRoughnessMapUv),x.push(S.diffuseRoughnessMapUv),x.push(S.iridescenceMapUv),x.push(S.iridescenceThicknessMapUv),x.push(S.sheenColorMapUv),x.push(S.sheenRoughnessMapUv),x.push(S.specularMapUv),x.push(S.specularColorMapUv),x.push(S.specularIntensityMapUv),x.push(S.transmissionMapUv),x.push(S.thicknessMapUv),x.push(S.combine),x.push(S.fogExp2),x.push(S.sizeAttenuation),x.push(S.morphTargetsCount),x.push(S.numSunLights),x.push(S.numDirLights),x.push(S.numPointLights),x.push(S.numSpotLights),x.push(S.numSpotLightMaps),x.push(S.numHemiLights),x.push(S.numRectAreaLights),x.push(S.numSunLightShadows),x.push(S.numDirLightShadows),x.push(S.numPointLightShadows),x.push(S.numSpotLightShadows),x.push(S.numSpotLightShadowsWithMaps),x.push(S.numLightProbes),x.push(S.numLightProbeGrids),x.push(S.shadowMapType),x.push(S.toneMapping),x.push(S.numClippingPlanes),x.push(S.numClipIntersection),x.push(S.depthPacking)}function b(x,S){r.disableAll(),S.instancing&&r.enable(0),S.instancingColor&&r.enable(1),S.instancingMorph&&r.enable(2),S.matcap&&r.enable(3),S.envMap&&r.enable(4),S.normalMapObjectSpace&&r.enable(5),S.normalMapTangentSpace&&r.enable(6),S.clearcoat&&r.enable(7),S.iridescence&&r.enable(8),S.alphaTest&&r.enable(9),S.vertexColors&&r.enable(10),S.vertexAlphas&&r.enable(11),S.vertexUv1s&&r.enable(12),S.vertexUv2s&&r.enable(13),S.vertexUv3s&&r.enable(14),S.vertexTangents&&r.enable(15),S.anisotropy&&r.enable(16),S.alphaHash&&r.enable(17),S.batching&&r.enable(18),S.dispersion&&r.enable(19),S.retroreflection&&r.enable(24),S.diffuseRoughness&&r.enable(25),S.batchingColor&&r.enable(20),S.gradientMap&&r.enable(21),S.packedNormalMap&&r.enable(22),S.vertexNormals&&r.enable(23),x.push(r.mask),r.disableAll(),S.fog&&r.enable(0),S.useFog&&r.enable(1),S.flatShading&&r.enable(2),S.logarithmicDepthBuffer&&r.enable(3),S.reversedDepthBuffer&&r.enable(4),S.skinning&&r.enable(5),S.morphTargets&&r.enable(6),S.morphNormals&&r.enable(7),S.morphColors&&r.enable(8),S.premultipliedAlpha&&r.enable(9),S.shadowMapEnabled&&r.enable(10),S.doubleSided&&r.enable(11),S.flipSided&&r.enable(12),S.useDepthPacking&&r.enable(13),S.dithering&&r.enable(14),S.transmission&&r.enable(15),S.sheen&&r.enable(16),S.opaque&&r.enable(17),S.pointsUvs&&r.enable(18),S.decodeVideoTexture&&r.enable(19),S.decodeVideoTextureEmissive&&r.enable(20),S.alphaToCoverage&&r.enable(21),S.numLightProbeGrids>0&&r.enable(22),S.hasPositionAttribute&&r.enable(23),x.push(r.mask)}function v(x){let S=d[x.type],E;if(S){let A=gn[S];E=Gr.clone(A.uniforms)}else E=x.uniforms;return E}function w(x,S){let E=h.get(S);return E!==void 0?++E.usedTimes:(E=new AM(i,S,x,a),l.push(E),h.set(S,E)),E}function p(x){if(--x.usedTimes===0){let S=l.indexOf(x);l[S]=l[l.length-1],l.pop(),h.delete(x.cacheKey),x.destroy()}}function _(x){o.remove(x)}function M(){o.dispose()}return{getParameters:m,getProgramCacheKey:y,getUniforms:v,acquireProgram:w,releaseProgram:p,releaseShaderCache:_,programs:l,dispose:M}}function RM(){let i=new WeakMap;function t(r){return i.has(r)}function e(r){let o=i.get(r);return o===void 0&&(o={},i.set(r,o)),o}function n(r){i.delete(r)}function a(r,o,c){i.get(r)[o]=c}function s(){i=new WeakMap}return{has:t,get:e,remove:n,update:a,dispose:s}}function CM(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.material.id!==t.material.id?i.material.id-t.material.id:i.materialVariant!==t.materialVariant?i.materialVariant-t.materialVariant:i.z!==t.z?i.z-t.z:i.id-t.id}function im(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.z!==t.z?t.z-i.z:i.id-t.id}function am(){let i=[],t=0,e=[],n=[],a=[];function s(){t=0,e.length=0,n.length=0,a.length=0}function r(d){let f=0;return d.isInstancedMesh&&(f+=2),d.isSkinnedMesh&&(f+=1),f}function o(d,f,m,y,g,b){let v=i[t];return v===void 0?(v={id:d.id,object:d,geometry:f,material:m,materialVariant:r(d),groupOrder:y,renderOrder:d.renderOrder,z:g,group:b},i[t]=v):(v.id=d.id,v.object=d,v.geometry=f,v.material=m,v.materialVariant=r(d),v.groupOrder=y,v.renderOrder=d.renderOrder,v.z=g,v.group=b),t++,v}function c(d,f,m,y,g,b,v){v.reversedDepth===!0&&(g=-g);let w=o(d,f,m,y,g,b);m.transmission>0?n.push(w):m.transparent===!0?a.push(w):e.push(w)}function l(d,f,m,y,g,b){let v=o(d,f,m,y,g,b);m.transmission>0?n.unshift(v):m.transparent===!0?a.unshift(v):e.unshift(v)}function h(d,f){e.length>1&&e.sort(d||CM),n.length>1&&n.sort(f||im),a.length>1&&a.sort(f||im)}function u(){for(let d=t,f=i.length;d<f;d++){let m=i[d];if(m.id===null)break;m.id=null,m.object=null,m.geometry=null,m.material=null,m.group=null}}return{opaque:e,transmissive:n,transparent:a,init:s,push:c,unshift:l,finish:u,sort:h}}function NM(){let i=new WeakMap;function t(n,a){let s=i.get(n),r;return s===void 0?(r=new am,i.set(n,[r])):a>=s.length?(r=new am,s.push(r)):r=s[a],r}function e(){i=new WeakMap}return{get:t,dispose:e}}function PM(){let i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={direction:new F,color:new kt};break;case"SpotLight":e={position:new F,direction:new F,color:new kt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":e={position:new F,color:new kt,distance:0,decay:0};break;case"HemisphereLight":e={direction:new F,skyColor:new kt,groundColor:new kt};break;case"RectAreaLight":e={color:new kt,position:new F,halfWidth:new F,halfHeight:new F};break}return i[t.id]=e,e}}}function LM(){let i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ct};break;case"SpotLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ct};break;case"PointLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ct,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[t.id]=e,e}}}function UM(i,t){return(t.castShadow?2:0)-(i.castShadow?2:0)+(t.map?1:0)-(i.map?1:0)}function OM(i){let t=new PM,e=LM(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)n.probe.push(new F);let a=new F,s=new Zt,r=new Zt;function o(l){let h=0,u=0,d=0;for(let C=0;C<9;C++)n.probe[C].set(0,0,0);let f=0,m=0,y=0,g=0,b=0,v=0,w=0,p=0,_=0,M=0,x=0,S=0,E=0,A=0;l.sort(UM);for(let C=0,L=l.length;C<L;C++){let N=l[C],U=N.color,z=N.intensity,B=N.distance,K=null;if(N.shadow&&N.shadow.map&&(N.shadow.map.texture.format===hi?K=N.shadow.map.texture:K=N.shadow.map.depthTexture||N.shadow.map.texture),N.isAmbientLight)h+=U.r*z,u+=U.g*z,d+=U.b*z;else if(N.isLightProbe){for(let W=0;W<9;W++)n.probe[W].addScaledVector(N.sh.coefficients[W],z);A++}else if(N.isSunLight){let W=t.get(N);if(W.color.copy(N.color).multiplyScalar(N.intensity),N.castShadow){let Y=N.shadow,tt=e.get(N);tt.shadowIntensity=Y.intensity,tt.shadowBias=Y.bias,tt.shadowNormalBias=Y.normalBias,tt.shadowRadius=Y.radius,tt.shadowMapSize.copy(Y.mapSize).multiply(Y.getFrameExtents()),n.sunShadow[m]=tt,n.sunShadowMap[m]=K;let gt=Y.getViewportCount();for(let It=0;It<gt;It++)n.sunShadowMatrix[y+It]=Y.getMatrix(It),n.sunShadowCascade[y+It]=Y._cascadeData[It];y+=gt,m++}n.sun[f]=W,f++}else if(N.isDirectionalLight){let W=t.get(N);if(W.color.copy(N.color).multiplyScalar(N.intensity),N.castShadow){let Y=N.shadow,tt=e.get(N);tt.shadowIntensity=Y.intensity,tt.shadowBias=Y.bias,tt.shadowNormalBias=Y.normalBias,tt.shadowRadius=Y.radius,tt.shadowMapSize=Y.mapSize,n.directionalShadow[g]=tt,n.directionalShadowMap[g]=K,n.directionalShadowMatrix[g]=N.shadow.matrix,_++}n.directional[g]=W,g++}else if(N.isSpotLight){let W=t.get(N);W.position.setFromMatrixPosition(N.matrixWorld),W.color.copy(U).multiplyScalar(z),W.distance=B,W.coneCos=Math.cos(N.angle),W.penumbraCos=Math.cos(N.angle*(1-N.penumbra)),W.decay=N.decay,n.spot[v]=W;let Y=N.shadow;if(N.map&&(n.spotLightMap[S]=N.map,S++,Y.updateMatrices(N),N.castShadow&&E++),n.spotLightMatrix[v]=Y.matrix,N.castShadow){let tt=e.get(N);tt.shadowIntensity=Y.intensity,tt.shadowBias=Y.bias,tt.shadowNormalBias=Y.normalBias,tt.shadowRadius=Y.radius,tt.shadowMapSize=Y.mapSize,n.spotShadow[v]=tt,n.spotShadowMap[v]=K,x++}v++}else if(N.isRectAreaLight){let W=t.get(N);W.color.copy(U).multiplyScalar(z),W.halfWidth.set(N.width*.5,0,0),W.halfHeight.set(0,N.height*.5,0),n.rectArea[w]=W,w++}else if(N.isPointLight){let W=t.get(N);if(W.color.copy(N.color).multiplyScalar(N.intensity),W.distance=N.distance,W.decay=N.decay,N.castShadow){let Y=N.shadow,tt=e.get(N);tt.shadowIntensity=Y.intensity,tt.shadowBias=Y.bias,tt.shadowNormalBias=Y.normalBias,tt.shadowRadius=Y.radius,tt.shadowMapSize=Y.mapSize,tt.shadowCameraNear=Y.camera.near,tt.shadowCameraFar=Y.camera.far,n.pointShadow[b]=tt,n.pointShadowMap[b]=K,n.pointShadowMatrix[b]=N.shadow.matrix,M++}n.point[b]=W,b++}else if(N.isHemisphereLight){let W=t.get(N);W.skyColor.copy(N.color).multiplyScalar(z),W.groundColor.copy(N.groundColor).multiplyScalar(z),n.hemi[p]=W,p++}}w>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=ft.LTC_FLOAT_1,n.rectAreaLTC2=ft.LTC_FLOAT_2):(n.rectAreaLTC1=ft.LTC_HALF_1,n.rectAreaLTC2=ft.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=u,n.ambient[2]=d;let R=n.hash;(R.sunLength!==f||R.directionalLength!==g||R.pointLength!==b||R.spotLength!==v||R.rectAreaLength!==w||R.hemiLength!==p||R.numSunShadows!==m||R.numDirectionalShadows!==_||R.numPointShadows!==M||R.numSpotShadows!==x||R.numSpotMaps!==S||R.numLightProbes!==A)&&(n.sun.length=f,n.directional.length=g,n.spot.length=v,n.rectArea.length=w,n.point.length=b,n.hemi.length=p,n.sunShadow.length=m,n.sunShadowMap.length=m,n.sunShadowMatrix.length=y,n.sunShadowCascade.length=y,n.directionalShadow.length=_,n.directionalShadowMap.length=_,n.directionalShadowMatrix.length=_,n.pointShadow.length=M,n.pointShadowMap.length=M,n.pointShadowMatrix.length=M,n.spotShadow.length=x,n.spotShadowMap.length=x,n.spotLightMatrix.length=x+S-E,n.spotLightMap.length=S,n.numSpotLightShadowsWithMaps=E,n.numLightProbes=A,R.sunLength=f,R.directionalLength=g,R.pointLength=b,R.spotLength=v,R.rectAreaLength=w,R.hemiLength=p,R.numSunShadows=m,R.numDirectionalShadows=_,R.numPointShadows=M,R.numSpotShadows=x,R.numSpotMaps=S,R.numLightProbes=A,n.version=DM++)}function c(l,h){let u=0,d=0,f=0,m=0,y=0,g=0,b=h.matrixWorldInverse;for(let v=0,w=l.length;v<w;v++){let p=l[v];if(p.isSunLight){let _=n.sun[u];_.direction.setFromMatrixPosition(p.matrixWorld),_.direction.transformDirection(b),u++}else if(p.isDirectionalLight){let _=n.directional[d];_.direction.setFromMatrixPosition(p.matrixWorld),a.setFromMatrixPosition(p.target.matrixWorld),_.direction.sub(a),_.direction.transformDirection(b),d++}else if(p.isSpotLight){let _=n.spot[m];_.position.setFromMatrixPosition(p.matrixWorld),_.position.applyMatrix4(b),_.direction.setFromMatrixPosition(p.matrixWorld),a.setFromMatrixPosition(p.target.matrixWorld),_.direction.sub(a),_.direction.transformDirection(b),m++}else if(p.isRectAreaLight){let _=n.rectArea[y];_.position.setFromMatrixPosition(p.matrixWorld),_.position.applyMatrix4(b),r.identity(),s.copy(p.matrixWorld),s.premultiply(b),r.extractRotation(s),_.halfWidth.set(p.width*.5,0,0),_.halfHeight.set(0,p.height*.5,0),_.halfWidth.applyMatrix4(r),_.halfHeight.applyMatrix4(r),y++}else if(p.isPointLight){let _=n.point[f];_.position.setFromMatrixPosition(p.matrixWorld),_.position.applyMatrix4(b),f++}else if(p.isHemisphereLight){let _=n.hemi[g];_.direction.setFromMatrixPosition(p.matrixWorld),_.direction.transformDirection(b),g++}}}return{setup:o,setupView:c,state:n}}function sm(i){let t=new OM(i),e=[],n=[],a=[];function s(u){h.camera=u,e.length=0,n.length=0,a.length=0}function r(u){u.isLightProbeGrid?a.push(u):e.push(u)}function o(u){n.push(u)}function c(){t.setup(e),a.sort((u,d)=>u.priority-d.priority||u.id-d.id)}function l(u){t.setupView(e,u)}let h={lightsArray:e,shadowsArray:n,lightProbeGridArray:a,camera:null,lights:t,transmissionRenderTarget:{},textureUnits:0};return{init:s,state:h,setupLights:c,setupLightsView:l,pushLight:r,pushShadow:o}}function FM(i){let t=new WeakMap;function e(a,s=0){let r=t.get(a),o;return r===void 0?(o=new sm(i),t.set(a,[o])):s>=r.length?(o=new sm(i),r.push(o)):o=r[s],o}function n(){t=new WeakMap}return{get:e,dispose:n}}function HM(i,t,e){let n=new Ci,a=new Ct,s=new Ct,r=new $t,o=new uc,c=new fc,l={},h=e.maxTextureSize,u={[ci]:Ge,[Ge]:ci,[kn]:kn},d=new Bn({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Ct},radius:{value:4}},vertexShader:BM,fragmentShader:kM}),f=d.clone();f.defines.HORIZONTAL_PASS=1;let m=new Ae;m.setAttribute("position",new un(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let y=new tn(m,d),g=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Pr;let b=this.type;this.render=function(M,x,S){if(g.enabled===!1||g.autoUpdate===!1&&g.needsUpdate===!1||M.length===0)return;this.type===ip&&(Rt("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Pr);let E=i.getRenderTarget(),A=i.getActiveCubeFace(),R=i.getActiveMipmapLevel(),C=i.state;C.setBlending(va),C.buffers.depth.getReversed()===!0?C.buffers.color.setClear(0,0,0,0):C.buffers.color.setClear(1,1,1,1),C.buffers.depth.setTest(!0),C.setScissorTest(!1);let L=b!==this.type;L&&x.traverse(function(N){N.material&&(Array.isArray(N.material)?N.material.forEach(U=>U.needsUpdate=!0):N.material.needsUpdate=!0)});for(let N=0,U=M.length;N<U;N++){let z=M[N],B=z.shadow;if(B===void 0){Rt("WebGLShadowMap:",z,"has no shadow.");continue}if(B.autoUpdate===!1&&B.needsUpdate===!1)continue;a.copy(B.mapSize);let K=B.getFrameExtents();a.multiply(K),s.copy(B.mapSize),(a.x>h||a.y>h)&&(a.x>h&&(s.x=Math.floor(h/K.x),a.x=s.x*K.x,B.mapSize.x=s.x),a.y>h&&(s.y=Math.floor(h/K.y),a.y=s.y*K.y,B.mapSize.y=s.y));let W=i.state.buffers.depth.getReversed();if(B.camera._reversedDepth=W,B.map===null||L===!0){if(B.map!==null&&(B.map.depthTexture!==null&&(B.map.depthTexture.dispose(),B.map.depthTexture=null),B.map.dispose()),this.type===ls){if(z.isPointLight){Rt("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}B.map=new In(a.x,a.y,{format:hi,type:Zn,minFilter:fn,magFilter:fn,generateMipmaps:!1}),B.map.texture.name=z.name+".shadowMap",B.map.depthTexture=new Ni(a.x,a.y,pn),B.map.depthTexture.name=z.name+".shadowMapDepth",B.map.depthTexture.format=Ii,B.map.depthTexture.compareFunction=null,B.map.depthTexture.minFilter=we,B.map.depthTexture.magFilter=we}else z.isPointLight?(B.map=new Xr(a.x),B.map.depthTexture=new pr(a.x,Mn)):(B.map=new In(a.x,a.y),B.map.depthTexture=new Ni(a.x,a.y,Mn)),B.map.depthTexture.name=z.name+".shadowMap",B.map.depthTexture.format=Ii,this.type===Pr?(B.map.depthTexture.compareFunction=W?fd:ud,B.map.depthTexture.minFilter=fn,B.map.depthTexture.magFilter=fn):(B.map.depthTexture.compareFunction=null,B.map.depthTexture.minFilter=we,B.map.depthTexture.magFilter=we);B.camera.updateProjectionMatrix()}B.map.isWebGLCubeRenderTarget!==!0&&(B.map.width!==a.x||B.map.height!==a.y)&&B.map.setSize(a.x,a.y);let Y=B.map.isWebGLCubeRenderTarget?6:B.getViewportCount();z.isPointLight!==!0&&B.updateMatrices(z,S);let tt=(B.camera.layers.mask&4294967294)!==0?B.camera.layers:S.layers;for(let gt=0;gt<Y;gt++){let It=B.getCamera(gt);if(z.isPointLight){let X=B.camera,it=B.matrix,_t=z.distance||X.far;_t!==X.far&&(X.far=_t,X.updateProjectionMatrix()),Wr.setFromMatrixPosition(z.matrixWorld),X.position.copy(Wr),Pd.copy(X.position),Pd.add(zM[gt]),X.up.copy(VM[gt]),X.lookAt(Pd),X.updateMatrixWorld(),it.makeTranslation(-Wr.x,-Wr.y,-Wr.z),rm.multiplyMatrices(X.projectionMatrix,X.matrixWorldInverse),B._frustum.setFromProjectionMatrix(rm,X.coordinateSystem,X.reversedDepth)}if(B.map.isWebGLCubeRenderTarget)i.setRenderTarget(B.map,gt),i.clear();else{gt===0&&(i.setRenderTarget(B.map),i.clear());let X=B.getViewport(gt);r.set(s.x*X.x,s.y*X.y,s.x*X.z,s.y*X.w),C.viewport(r)}n=B.getFrustum(gt),p(x,S,It,z,tt,this.type)}B.isPointLightShadow!==!0&&this.type===ls&&v(B,S),B.needsUpdate=!1}b=this.type,g.needsUpdate=!1,i.setRenderTarget(E,A,R)};function v(M,x){let S=t.update(y);d.defines.VSM_SAMPLES!==M.blurSamples&&(d.defines.VSM_SAMPLES=M.blurSamples,f.defines.VSM_SAMPLES=M.blurSamples,d.needsUpdate=!0,f.needsUpdate=!0),M.mapPass===null?M.mapPass=new In(a.x,a.y,{format:hi,type:Zn}):(M.mapPass.width!==M.map.width||M.mapPass.height!==M.map.height)&&M.mapPass.setSize(M.map.width,M.map.height),d.uniforms.shadow_pass.value=M.map.depthTexture,d.uniforms.resolution.value.set(M.map.width,M.map.height),d.uniforms.radius.value=M.radius,i.setRenderTarget(M.mapPass),i.clear(),i.renderBufferDirect(x,null,S,d,y,null),f.uniforms.shadow_pass.value=M.mapPass.texture,f.uniforms.resolution.value.set(M.map.width,M.map.height),f.uniforms.radius.value=M.radius,i.setRenderTarget(M.map),i.clear(),i.renderBufferDirect(x,null,S,f,y,null)}function w(M,x,S,E){let A=null,R=S.isPointLight===!0?M.customDistanceMaterial:M.customDepthMaterial;if(R!==void 0)A=R;else if(A=S.isPointLight===!0?c:o,i.localClippingEnabled&&x.clipShadows===!0&&Array.isArray(x.clippingPlanes)&&x.clippingPlanes.length!==0||x.displacementMap&&x.displacementScale!==0||x.alphaMap&&x.alphaTest>0||x.map&&x.alphaTest>0||x.alphaToCoverage===!0){let C=A.uuid,L=x.uuid,N=l[C];N===void 0&&(N={},l[C]=N);let U=N[L];U===void 0&&(U=A.clone(),N[L]=U,x.addEventListener("dispose",_)),A=U}if(A.visible=x.visible,A.wireframe=x.wireframe,E===ls?A.side=x.shadowSide!==null?x.shadowSide:x.side:A.side=x.shadowSide!==null?x.shadowSide:u[x.side],A.alphaMap=x.alphaMap,A.alphaTest=x.alphaToCoverage===!0?.5:x.alphaTest,A.map=x.map,A.clipShadows=x.clipShadows,A.clippingPlanes=x.clippingPlanes,A.clipIntersection=x.clipIntersection,A.displacementMap=x.displacementMap,A.displacementScale=x.displacementScale,A.displacementBias=x.displacementBias,A.wireframeLinewidth=x.wireframeLinewidth,A.linewidth=x.linewidth,S.isPointLight===!0&&A.isMeshDistanceMaterial===!0){let C=i.properties.get(A);C.light=S}return A}function p(M,x,S,E,A,R){if(M.visible===!1)return;if(M.layers.test(A)&&(M.isMesh||M.isLine||M.isPoints)&&(M.castShadow||M.receiveShadow&&R===ls)&&(!M.frustumCulled||M.intersectsFrustum(n))){M.modelViewMatrix.multiplyMatrices(S.matrixWorldInverse,M.matrixWorld);let N=t.update(M),U=M.material;if(Array.isArray(U)){let z=N.groups;for(let B=0,K=z.length;B<K;B++){let W=z[B],Y=U[W.materialIndex];if(Y&&Y.visible){let tt=w(M,Y,E,R);M.onBeforeShadow(i,M,x,S,N,tt,W),i.renderBufferDirect(S,null,N,tt,M,W),M.onAfterShadow(i,M,x,S,N,tt,W)}}}else if(U.visible){let z=w(M,U,E,R);M.onBeforeShadow(i,M,x,S,N,z,null),i.renderBufferDirect(S,null,N,z,M,null),M.onAfterShadow(i,M,x,S,N,z,null)}}let L=M.children;for(let N=0,U=L.length;N<U;N++)p(L[N],x,S,E,A,R)}function _(M){M.target.removeEventListener("dispose",_);for(let S in l){let E=l[S],A=M.target.uuid;A in E&&(E[A].dispose(),delete E[A])}}}function GM(i,t){function e(){let D=!1,$=new $t,q=null,lt=new $t(0,0,0,0);return{setMask:function(st){q!==st&&!D&&(i.colorMask(st,st,st,st),q=st)},setLocked:function(st){D=st},setClear:function(st,ot,At,Vt,at){at===!0&&(st*=Vt,ot*=Vt,At*=Vt),$.set(st,ot,At,Vt),lt.equals($)===!1&&(i.clearColor(st,ot,At,Vt),lt.copy($))},reset:function(){D=!1,q=null,lt.set(-1,0,0,0)}}}function n(){let D=!1,$=!1,q=null,lt=null,st=null;return{setReversed:function(ot){if($!==ot){let At=t.get("EXT_clip_control");ot?At.clipControlEXT(At.LOWER_LEFT_EXT,At.ZERO_TO_ONE_EXT):At.clipControlEXT(At.LOWER_LEFT_EXT,At.NEGATIVE_ONE_TO_ONE_EXT),$=ot;let Vt=st;st=null,this.setClear(Vt)}},getReversed:function(){return $},setTest:function(ot){ot?pt(i.DEPTH_TEST):Ut(i.DEPTH_TEST)},setMask:function(ot){q!==ot&&!D&&(i.depthMask(ot),q=ot)},setFunc:function(ot){if($&&(ot=Op[ot]),lt!==ot){switch(ot){case Yo:i.depthFunc(i.NEVER);break;case Jo:i.depthFunc(i.ALWAYS);break;case Ko:i.depthFunc(i.LESS);break;case Ka:i.depthFunc(i.LEQUAL);break;case Zo:i.depthFunc(i.EQUAL);break;case $o:i.depthFunc(i.GEQUAL);break;case Qo:i.depthFunc(i.GREATER);break;case tc:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}lt=ot}},setLocked:function(ot){D=ot},setClear:function(ot){st!==ot&&(st=ot,$&&(ot=1-ot),i.clearDepth(ot))},reset:function(){D=!1,q=null,lt=null,st=null,$=!1}}}function a(){let D=!1,$=null,q=null,lt=null,st=null,ot=null,At=null,Vt=null,at=null;return{setTest:function(Tt){D||(Tt?pt(i.STENCIL_TEST):Ut(i.STENCIL_TEST))},setMask:function(Tt){$!==Tt&&!D&&(i.stencilMask(Tt),$=Tt)},setFunc:function(Tt,zt,bt){(q!==Tt||lt!==zt||st!==bt)&&(i.stencilFunc(Tt,zt,bt),q=Tt,lt=zt,st=bt)},setOp:function(Tt,zt,bt){(ot!==Tt||At!==zt||Vt!==bt)&&(i.stencilOp(Tt,zt,bt),ot=Tt,At=zt,Vt=bt)},setLocked:function(Tt){D=Tt},setClear:function(Tt){at!==Tt&&(i.clearStencil(Tt),at=Tt)},reset:function(){D=!1,$=null,q=null,lt=null,st=null,ot=null,At=null,Vt=null,at=null}}}let s=new e,r=new n,o=new a,c={},l=new WeakMap,h={},u={},d={},f=new WeakMap,m=[],y=null,g=!1,b=null,v=null,w=null,p=null,_=null,M=null,x=null,S=new kt(0,0,0),E=0,A=!1,R=null,C=null,L=null,N=null,U=null,z=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS),B=!1,K=0,W=i.getParameter(i.VERSION);W.indexOf("WebGL")!==-1?(K=parseFloat(/^WebGL (\d)/.exec(W)[1]),B=K>=1):W.indexOf("OpenGL ES")!==-1&&(K=parseFloat(/^OpenGL ES (\d)/.exec(W)[1]),B=K>=2);let Y=null,tt={},gt=i.getParameter(i.SCISSOR_BOX),It=i.getParameter(i.VIEWPORT),X=new $t().fromArray(gt),it=new $t().fromArray(It);function _t(D,$,q,lt){let st=new Uint8Array(4),ot=i.createTexture();i.bindTexture(D,ot),i.texParameteri(D,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(D,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let At=0;At<q;At++)D===i.TEXTURE_3D||D===i.TEXTURE_2D_ARRAY?i.texImage3D($,0,i.RGBA,1,1,lt,0,i.RGBA,i.UNSIGNED_BYTE,st):i.texImage2D($+At,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,st);return ot}let Et={};Et[i.TEXTURE_2D]=_t(i.TEXTURE_2D,i.TEXTURE_2D,1),Et[i.TEXTURE_CUBE_MAP]=_t(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),Et[i.TEXTURE_2D_ARRAY]=_t(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),Et[i.TEXTURE_3D]=_t(i.TEXTURE_3D,i.TEXTURE_3D,1,1),s.setClear(0,0,0,1),r.setClear(1),o.setClear(0),pt(i.DEPTH_TEST),r.setFunc(Ka),yn(!1),ge(Yh),pt(i.CULL_FACE),Ve(va);function pt(D){h[D]!==!0&&(i.enable(D),h[D]=!0)}function Ut(D){h[D]!==!1&&(i.disable(D),h[D]=!1)}function ye(D,$){return d[D]!==$?(i.bindFramebuffer(D,$),d[D]=$,D===i.DRAW_FRAMEBUFFER&&(d[i.FRAMEBUFFER]=$),D===i.FRAMEBUFFER&&(d[i.DRAW_FRAMEBUFFER]=$),!0):!1}function Nt(D,$){let q=m,lt=!1;if(D){q=f.get($),q===void 0&&(q=[],f.set($,q));let st=D.textures;if(q.length!==st.length||q[0]!==i.COLOR_ATTACHMENT0){for(let ot=0,At=st.length;ot<At;ot++)q[ot]=i.COLOR_ATTACHMENT0+ot;q.length=st.length,lt=!0}}else q[0]!==i.BACK&&(q[0]=i.BACK,lt=!0);lt&&i.drawBuffers(q)}function Jt(D){return y!==D?(i.useProgram(D),y=D,!0):!1}let ce={[Ma]:i.FUNC_ADD,[sp]:i.FUNC_SUBTRACT,[rp]:i.FUNC_REVERSE_SUBTRACT};ce[op]=i.MIN,ce[cp]=i.MAX;let jt={[lp]:i.ZERO,[hp]:i.ONE,[dp]:i.SRC_COLOR,[$h]:i.SRC_ALPHA,[bp]:i.SRC_ALPHA_SATURATE,[mp]:i.DST_COLOR,[fp]:i.DST_ALPHA,[up]:i.ONE_MINUS_SRC_COLOR,[Qh]:i.ONE_MINUS_SRC_ALPHA,[gp]:i.ONE_MINUS_DST_COLOR,[pp]:i.ONE_MINUS_DST_ALPHA,[xp]:i.CONSTANT_COLOR,[yp]:i.ONE_MINUS_CONSTANT_COLOR,[_p]:i.CONSTANT_ALPHA,[vp]:i.ONE_MINUS_CONSTANT_ALPHA};function Ve(D,$,q,lt,st,ot,At,Vt,at,Tt){if(D===va){g===!0&&(Ut(i.BLEND),g=!1);return}if(g===!1&&(pt(i.BLEND),g=!0),D!==ap){if(D!==b||Tt!==A){if((v!==Ma||_!==Ma)&&(i.blendEquation(i.FUNC_ADD),v=Ma,_=Ma),Tt)switch(D){case hs:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Jh:i.blendFunc(i.ONE,i.ONE);break;case Kh:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case Zh:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:Lt("WebGLState: Invalid blending: ",D);break}else switch(D){case hs:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Jh:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case Kh:Lt("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Zh:Lt("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:Lt("WebGLState: Invalid blending: ",D);break}w=null,p=null,M=null,x=null,S.set(0,0,0),E=0,b=D,A=Tt}return}st=st||$,ot=ot||q,At=At||lt,($!==v||st!==_)&&(i.blendEquationSeparate(ce[$],ce[st]),v=$,_=st),(q!==w||lt!==p||ot!==M||At!==x)&&(i.blendFuncSeparate(jt[q],jt[lt],jt[ot],jt[At]),w=q,p=lt,M=ot,x=At),(Vt.equals(S)===!1||at!==E)&&(i.blendColor(Vt.r,Vt.g,Vt.b,at),S.copy(Vt),E=at),b=D,A=!1}function Ee(D,$){D.side===kn?Ut(i.CULL_FACE):pt(i.CULL_FACE);let q=D.side===Ge;$&&(q=!q),yn(q),D.blending===hs&&D.transparent===!1?Ve(va):Ve(D.blending,D.blendEquation,D.blendSrc,D.blendDst,D.blendEquationAlpha,D.blendSrcAlpha,D.blendDstAlpha,D.blendColor,D.blendAlpha,D.premultipliedAlpha),r.setFunc(D.depthFunc),r.setTest(D.depthTest),r.setMask(D.depthWrite),s.setMask(D.colorWrite);let lt=D.stencilWrite;o.setTest(lt),lt&&(o.setMask(D.stencilWriteMask),o.setFunc(D.stencilFunc,D.stencilRef,D.stencilFuncMask),o.setOp(D.stencilFail,D.stencilZFail,D.stencilZPass)),De(D.polygonOffset,D.polygonOffsetFactor,D.polygonOffsetUnits),D.alphaToCoverage===!0?pt(i.SAMPLE_ALPHA_TO_COVERAGE):Ut(i.SAMPLE_ALPHA_TO_COVERAGE)}function yn(D){R!==D&&(D?i.frontFace(i.CW):i.frontFace(i.CCW),R=D)}function ge(D){D!==ep?(pt(i.CULL_FACE),D!==C&&(D===Yh?i.cullFace(i.BACK):D===np?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):Ut(i.CULL_FACE),C=D}function ei(D){D!==L&&(B&&i.lineWidth(D),L=D)}function De(D,$,q){D?(pt(i.POLYGON_OFFSET_FILL),(N!==$||U!==q)&&(N=$,U=q,r.getReversed()&&($=-$,q=-q),i.polygonOffset($,q))):Ut(i.POLYGON_OFFSET_FILL)}function Pn(D){D?pt(i.SCISSOR_TEST):Ut(i.SCISSOR_TEST)}function Ln(D){D===void 0&&(D=i.TEXTURE0+z-1),Y!==D&&(i.activeTexture(D),Y=D)}function Dn(D,$,q){q===void 0&&(Y===null?q=i.TEXTURE0+z-1:q=Y);let lt=tt[q];lt===void 0&&(lt={type:void 0,texture:void 0},tt[q]=lt),(lt.type!==D||lt.texture!==$)&&(Y!==q&&(i.activeTexture(q),Y=q),i.bindTexture(D,$||Et[D]),lt.type=D,lt.texture=$)}function k(){let D=tt[Y];D!==void 0&&D.type!==void 0&&(i.bindTexture(D.type,null),D.type=void 0,D.texture=void 0)}function Un(){try{i.compressedTexImage2D(...arguments)}catch(D){Lt("WebGLState:",D)}}function pe(){try{i.compressedTexImage3D(...arguments)}catch(D){Lt("WebGLState:",D)}}function me(){try{i.texSubImage2D(...arguments)}catch(D){Lt("WebGLState:",D)}}function mt(){try{i.texSubImage3D(...arguments)}catch(D){Lt("WebGLState:",D)}}function Te(){try{i.compressedTexSubImage2D(...arguments)}catch(D){Lt("WebGLState:",D)}}function Pt(){try{i.compressedTexSubImage3D(...arguments)}catch(D){Lt("WebGLState:",D)}}function Ot(){try{i.texStorage2D(...arguments)}catch(D){Lt("WebGLState:",D)}}function P(){try{i.texStorage3D(...arguments)}catch(D){Lt("WebGLState:",D)}}function T(){try{i.texImage2D(...arguments)}catch(D){Lt("WebGLState:",D)}}function H(){try{i.texImage3D(...arguments)}catch(D){Lt("WebGLState:",D)}}function nt(D){return u[D]!==void 0?u[D]:i.getParameter(D)}function Q(D,$){u[D]!==$&&(i.pixelStorei(D,$),u[D]=$)}function rt(D){X.equals(D)===!1&&(i.scissor(D.x,D.y,D.z,D.w),X.copy(D))}function dt(D){it.equals(D)===!1&&(i.viewport(D.x,D.y,D.z,D.w),it.copy(D))}function J(D,$){let q=l.get($);q===void 0&&(q=new WeakMap,l.set($,q));let lt=q.get(D);lt===void 0&&(lt=i.getUniformBlockIndex($,D.name),i.uniformBlockBinding($,lt,lt),q.set(D,lt))}function Z(D,$,q){let st=l.get($).get(D);c[st]!==q&&(i.bindBufferBase(i.UNIFORM_BUFFER,st,q),c[st]=q)}function ct(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),r.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},u={},Y=null,tt={},d={},c={},f=new WeakMap,m=[],y=null,g=!1,b=null,v=null,w=null,p=null,_=null,M=null,x=null,S=new kt(0,0,0),E=0,A=!1,R=null,C=null,L=null,N=null,U=null,X.set(0,0,i.canvas.width,i.canvas.height),it.set(0,0,i.canvas.width,i.canvas.height),s.reset(),r.reset(),o.reset()}return{buffers:{color:s,depth:r,stencil:o},enable:pt,disable:Ut,bindFramebuffer:ye,drawBuffers:Nt,useProgram:Jt,setBlending:Ve,setMaterial:Ee,setFlipSided:yn,setCullFace:ge,setLineWidth:ei,setPolygonOffset:De,setScissorTest:Pn,activeTexture:Ln,bindTexture:Dn,unbindTexture:k,compressedTexImage2D:Un,compressedTexImage3D:pe,texImage2D:T,texImage3D:H,pixelStorei:Q,getParameter:nt,updateUBOMapping:J,uniformBlockBinding:Z,texStorage2D:Ot,texStorage3D:P,texSubImage2D:me,texSubImage3D:mt,compressedTexSubImage2D:Te,compressedTexSubImage3D:Pt,scissor:rt,viewport:dt,reset:ct}}function WM(i,t,e,n,a,s,r){let o=t.has("WEBGL_multisampled_render_to_texture")?t.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new Ct,h=new WeakMap,u=new Set,d,f=new WeakMap,m=new Set,y=new FinalizationRegistry(P=>m.delete(P)),g=!1;try{g=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function b(P,T){return g?new OffscreenCanvas(P,T):ir("canvas")}function v(P,T,H){let nt=1,Q=Ot(P);if((Q.width>H||Q.height>H)&&(nt=H/Math.max(Q.width,Q.height)),nt<1)if(typeof HTMLImageElement<"u"&&P instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&P instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&P instanceof ImageBitmap||typeof VideoFrame<"u"&&P instanceof VideoFrame){let rt=Math.floor(nt*Q.width),dt=Math.floor(nt*Q.height);d===void 0&&(d=b(rt,dt));let J=T?b(rt,dt):d;return J.width=rt,J.height=dt,J.getContext("2d").drawImage(P,0,0,rt,dt),Rt("WebGLRenderer: Texture has been resized from ("+Q.width+"x"+Q.height+") to ("+rt+"x"+dt+")."),J}else return"data"in P&&Rt("WebGLRenderer: Image in DataTexture is too big ("+Q.width+"x"+Q.height+")."),P;return P}function w(P){return P.generateMipmaps}function p(P){i.generateMipmap(P)}function _(P){return P.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:P.isWebGL3DRenderTarget?i.TEXTURE_3D:P.isWebGLArrayRenderTarget||P.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function M(P,T,H,nt,Q,rt=!1){if(P!==null){if(i[P]!==void 0)return i[P];Rt("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+P+"'")}let dt;nt&&(dt=t.get("EXT_texture_norm16"),dt||Rt("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let J=T;if(T===i.RED&&(H===i.FLOAT&&(J=i.R32F),H===i.HALF_FLOAT&&(J=i.R16F),H===i.UNSIGNED_BYTE&&(J=i.R8),H===i.UNSIGNED_SHORT&&dt&&(J=dt.R16_EXT),H===i.SHORT&&dt&&(J=dt.R16_SNORM_EXT)),T===i.RED_INTEGER&&(H===i.UNSIGNED_BYTE&&(J=i.R8UI),H===i.UNSIGNED_SHORT&&(J=i.R16UI),H===i.UNSIGNED_INT&&(J=i.R32UI),H===i.BYTE&&(J=i.R8I),H===i.SHORT&&(J=i.R16I),H===i.INT&&(J=i.R32I)),T===i.RG&&(H===i.FLOAT&&(J=i.RG32F),H===i.HALF_FLOAT&&(J=i.RG16F),H===i.UNSIGNED_BYTE&&(J=i.RG8),H===i.UNSIGNED_SHORT&&dt&&(J=dt.RG16_EXT),H===i.SHORT&&dt&&(J=dt.RG16_SNORM_EXT)),T===i.RG_INTEGER&&(H===i.UNSIGNED_BYTE&&(J=i.RG8UI),H===i.UNSIGNED_SHORT&&(J=i.RG16UI),H===i.UNSIGNED_INT&&(J=i.RG32UI),H===i.BYTE&&(J=i.RG8I),H===i.SHORT&&(J=i.RG16I),H===i.INT&&(J=i.RG32I)),T===i.RGB_INTEGER&&(H===i.UNSIGNED_BYTE&&(J=i.RGB8UI),H===i.UNSIGNED_SHORT&&(J=i.RGB16UI),H===i.UNSIGNED_INT&&(J=i.RGB32UI),H===i.BYTE&&(J=i.RGB8I),H===i.SHORT&&(J=i.RGB16I),H===i.INT&&(J=i.RGB32I)),T===i.RGBA_INTEGER&&(H===i.UNSIGNED_BYTE&&(J=i.RGBA8UI),H===i.UNSIGNED_SHORT&&(J=i.RGBA16UI),H===i.UNSIGNED_INT&&(J=i.RGBA32UI),H===i.BYTE&&(J=i.RGBA8I),H===i.SHORT&&(J=i.RGBA16I),H===i.INT&&(J=i.RGBA32I)),T===i.RGB&&(H===i.UNSIGNED_SHORT&&dt&&(J=dt.RGB16_EXT),H===i.SHORT&&dt&&(J=dt.RGB16_SNORM_EXT),H===i.UNSIGNED_INT_5_9_9_9_REV&&(J=i.RGB9_E5),H===i.UNSIGNED_INT_10F_11F_11F_REV&&(J=i.R11F_G11F_B10F)),T===i.RGBA){let Z=rt?nr:Gt.getTransfer(Q);H===i.FLOAT&&(J=i.RGBA32F),H===i.HALF_FLOAT&&(J=i.RGBA16F),H===i.UNSIGNED_BYTE&&(J=Z===ie?i.SRGB8_ALPHA8:i.RGBA8),H===i.UNSIGNED_SHORT&&dt&&(J=dt.RGBA16_EXT),H===i.SHORT&&dt&&(J=dt.RGBA16_SNORM_EXT),H===i.UNSIGNED_SHORT_4_4_4_4&&(J=i.RGBA4),H===i.UNSIGNED_SHORT_5_5_5_1&&(J=i.RGB5_A1)}return(J===i.R16F||J===i.R32F||J===i.RG16F||J===i.RG32F||J===i.RGBA16F||J===i.RGBA32F)&&t.get("EXT_color_buffer_float"),J}function x(P,T){let H;return P?T===null||T===Mn||T===wa?H=i.DEPTH24_STENCIL8:T===pn?H=i.DEPTH32F_STENCIL8:T===Qi&&(H=i.DEPTH24_STENCIL8,Rt("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):T===null||T===Mn||T===wa?H=i.DEPTH_COMPONENT24:T===pn?H=i.DEPTH_COMPONENT32F:T===Qi&&(H=i.DEPTH_COMPONENT16),H}function S(P,T){return w(P)===!0||P.isFramebufferTexture&&P.minFilter!==we&&P.minFilter!==fn?Math.log2(Math.max(T.width,T.height))+1:P.mipmaps.length>0?P.mipmaps.length:P.isCompressedTexture&&Array.isArray(P.image)?T.mipmaps.length:1}function E(P){let T=new WeakRef(P);n.get(P).__ref=T,m.add(T),y.register(P,T,T)}function A(P){let T=n.get(P).__ref;T!==void 0&&(m.delete(T),y.unregister(T))}function R(P){L(P.target)}function C(P){N(P.target)}function L(P){P.removeEventListener("dispose",R),A(P),z(P),P.isVideoTexture&&h.delete(P),P.isHTMLTexture&&u.delete(P)}function N(P){P.removeEventListener("dispose",C),A(P),K(P)}function U(){for(let P of m){let T=P.deref();T!==void 0&&(T.isRenderTarget===!0?N(T):L(T))}m.clear(),u.clear()}function z(P){let T=n.get(P);if(T.__webglInit===void 0)return;let H=P.source,nt=f.get(H);if(nt){let Q=nt[T.__cacheKey];Q.usedTimes--,Q.usedTimes===0&&B(P),Object.keys(nt).length===0&&f.delete(H)}n.remove(P)}function B(P){let T=n.get(P);i.deleteTexture(T.__webglTexture);let H=P.source,nt=f.get(H);delete nt[T.__cacheKey],r.memory.textures--}function K(P){let T=n.get(P);T.__depthDisposeCallback&&T.__depthDisposeCallback();let H=P.depthTexture;if(H&&H.renderTarget===P&&L(H),P.isWebGLCubeRenderTarget)for(let Q=0;Q<6;Q++){if(Array.isArray(T.__webglFramebuffer[Q]))for(let rt=0;rt<T.__webglFramebuffer[Q].length;rt++)i.deleteFramebuffer(T.__webglFramebuffer[Q][rt]);else i.deleteFramebuffer(T.__webglFramebuffer[Q]);T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer[Q])}else{if(Array.isArray(T.__webglFramebuffer))for(let Q=0;Q<T.__webglFramebuffer.length;Q++)i.deleteFramebuffer(T.__webglFramebuffer[Q]);else i.deleteFramebuffer(T.__webglFramebuffer);if(T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer),T.__webglMultisampledFramebuffer&&i.deleteFramebuffer(T.__webglMultisampledFramebuffer),T.__webglColorRenderbuffer)for(let Q=0;Q<T.__webglColorRenderbuffer.length;Q++)T.__webglColorRenderbuffer[Q]&&i.deleteRenderbuffer(T.__webglColorRenderbuffer[Q]);T.__webglDepthRenderbuffer&&i.deleteRenderbuffer(T.__webglDepthRenderbuffer)}let nt=P.textures;for(let Q=0,rt=nt.length;Q<rt;Q++){let dt=n.get(nt[Q]);dt.__webglTexture&&(i.deleteTexture(dt.__webglTexture),r.memory.textures--),n.remove(nt[Q])}n.remove(P)}let W=0;function Y(){W=0}function tt(){return W}function gt(P){W=P}function It(){let P=W;return P>=a.maxTextures&&Rt("WebGLTextures: Trying to use "+(P+1)+" texture units while this GPU supports only "+a.maxTextures),W+=1,P}function X(P){let T=[];return T.push(P.wrapS),T.push(P.wrapT),T.push(P.wrapR||0),T.push(P.magFilter),T.push(P.minFilter),T.push(P.anisotropy),T.push(P.internalFormat),T.push(P.format),T.push(P.type),T.push(P.generateMipmaps),T.push(P.mipmapsAutoUpdate),T.push(P.premultiplyAlpha),T.push(P.flipY),T.push(P.unpackAlignment),T.push(P.colorSpace),T.join()}function it(P,T){let H=n.get(P);if(P.isVideoTexture&&Te(P),P.isRenderTargetTexture===!1&&P.isExternalTexture!==!0&&P.version>0&&H.__version!==P.version){let nt=P.image;if(nt===null)Rt("WebGLRenderer: Texture marked for update but no image data found.");else if(nt.complete===!1)Rt("WebGLRenderer: Texture marked for update but image is incomplete");else{Ee(H,P,T);return}}else P.isExternalTexture&&(H.__webglTexture=P.sourceTexture?P.sourceTexture:null);e.bindTexture(i.TEXTURE_2D,H.__webglTexture,i.TEXTURE0+T)}function _t(P,T){let H=n.get(P);if(P.isRenderTargetTexture===!1&&P.version>0&&H.__version!==P.version){Ee(H,P,T);return}else P.isExternalTexture&&(H.__webglTexture=P.sourceTexture?P.sourceTexture:null);e.bindTexture(i.TEXTURE_2D_ARRAY,H.__webglTexture,i.TEXTURE0+T)}function Et(P,T){let H=n.get(P);if(P.isRenderTargetTexture===!1&&P.version>0&&H.__version!==P.version){Ee(H,P,T);return}e.bindTexture(i.TEXTURE_3D,H.__webglTexture,i.TEXTURE0+T)}function pt(P,T){let H=n.get(P);if(P.version>0&&H.__version!==P.version){yn(H,P,T);return}e.bindTexture(i.TEXTURE_CUBE_MAP,H.__webglTexture,i.TEXTURE0+T)}let Ut={[ec]:i.REPEAT,[si]:i.CLAMP_TO_EDGE,[nc]:i.MIRRORED_REPEAT},ye={[we]:i.NEAREST,[wp]:i.NEAREST_MIPMAP_NEAREST,[Lr]:i.NEAREST_MIPMAP_LINEAR,[fn]:i.LINEAR,[Nc]:i.LINEAR_MIPMAP_NEAREST,[Pi]:i.LINEAR_MIPMAP_LINEAR},Nt={[Ip]:i.NEVER,[pd]:i.ALWAYS,[Rp]:i.LESS,[ud]:i.LEQUAL,[Cp]:i.EQUAL,[fd]:i.GEQUAL,[Np]:i.GREATER,[Pp]:i.NOTEQUAL};function Jt(P,T){if(T.type===pn&&t.has("OES_texture_float_linear")===!1&&(T.magFilter===fn||T.magFilter===Nc||T.magFilter===Lr||T.magFilter===Pi||T.minFilter===fn||T.minFilter===Nc||T.minFilter===Lr||T.minFilter===Pi)&&Rt("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(P,i.TEXTURE_WRAP_S,Ut[T.wrapS]),i.texParameteri(P,i.TEXTURE_WRAP_T,Ut[T.wrapT]),(P===i.TEXTURE_3D||P===i.TEXTURE_2D_ARRAY)&&i.texParameteri(P,i.TEXTURE_WRAP_R,Ut[T.wrapR]),i.texParameteri(P,i.TEXTURE_MAG_FILTER,ye[T.magFilter]),i.texParameteri(P,i.TEXTURE_MIN_FILTER,ye[T.minFilter]),T.compareFunction&&(i.texParameteri(P,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(P,i.TEXTURE_COMPARE_FUNC,Nt[T.compareFunction])),t.has("EXT_texture_filter_anisotropic")===!0){if(T.magFilter===we||T.minFilter!==Lr&&T.minFilter!==Pi||T.type===pn&&t.has("OES_texture_float_linear")===!1)return;if(T.anisotropy>1||n.get(T).__currentAnisotropy){let H=t.get("EXT_texture_filter_anisotropic");i.texParameterf(P,H.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(T.anisotropy,a.getMaxAnisotropy())),n.get(T).__currentAnisotropy=T.anisotropy}}}function ce(P,T){let H=!1;P.__webglInit===void 0&&(P.__webglInit=!0,T.addEventListener("dispose",R),E(T));let nt=T.source,Q=f.get(nt);Q===void 0&&(Q={},f.set(nt,Q));let rt=X(T);if(rt!==P.__cacheKey){Q[rt]===void 0&&(Q[rt]={texture:i.createTexture(),usedTimes:0},r.memory.textures++,H=!0),Q[rt].usedTimes++;let dt=Q[P.__cacheKey];dt!==void 0&&(Q[P.__cacheKey].usedTimes--,dt.usedTimes===0&&B(T)),P.__cacheKey=rt,P.__webglTexture=Q[rt].texture}return H}function jt(P,T,H){return Math.floor(Math.floor(P/H)/T)}function Ve(P,T,H,nt){let rt=P.updateRanges;if(rt.length===0)e.texSubImage2D(i.TEXTURE_2D,0,0,0,T.width,T.height,H,nt,T.data);else{rt.sort((D,$)=>D.start-$.start);let dt=0;for(let D=1;D<rt.length;D++){let $=rt[dt],q=rt[D],lt=$.start+$.count,st=jt(q.start,T.width,4),ot=jt($.start,T.width,4);q.start<=lt+1&&st===ot&&jt(q.start+q.count-1,T.width,4)===st?$.count=Math.max($.count,q.start+q.count-$.start):(++dt,rt[dt]=q)}rt.length=dt+1;let J=e.getParameter(i.UNPACK_ROW_LENGTH),Z=e.getParameter(i.UNPACK_SKIP_PIXELS),ct=e.getParameter(i.UNPACK_SKIP_ROWS);e.pixelStorei(i.UNPACK_ROW_LENGTH,T.width);for(let D=0,$=rt.length;D<$;D++){let q=rt[D],lt=Math.floor(q.start/4),st=Math.ceil(q.count/4),ot=lt%T.width,At=Math.floor(lt/T.width),Vt=st,at=1;e.pixelStorei(i.UNPACK_SKIP_PIXELS,ot),e.pixelStorei(i.UNPACK_SKIP_ROWS,At),e.texSubImage2D(i.TEXTURE_2D,0,ot,At,Vt,at,H,nt,T.data)}P.clearUpdateRanges(),e.pixelStorei(i.UNPACK_ROW_LENGTH,J),e.pixelStorei(i.UNPACK_SKIP_PIXELS,Z),e.pixelStorei(i.UNPACK_SKIP_ROWS,ct)}}function Ee(P,T,H){let nt=i.TEXTURE_2D;(T.isDataArrayTexture||T.isCompressedArrayTexture)&&(nt=i.TEXTURE_2D_ARRAY),T.isData3DTexture&&(nt=i.TEXTURE_3D);let Q=ce(P,T),rt=T.source;e.bindTexture(nt,P.__webglTexture,i.TEXTURE0+H);let dt=n.get(rt);if(rt.version!==dt.__version||Q===!0){if(e.activeTexture(i.TEXTURE0+H),(typeof ImageBitmap<"u"&&T.image instanceof ImageBitmap)===!1){let at=Gt.getPrimaries(Gt.workingColorSpace),Tt=T.colorSpace===Di?null:Gt.getPrimaries(T.colorSpace),zt=T.colorSpace===Di||at===Tt?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,zt)}e.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment);let Z=v(T.image,!1,a.maxTextureSize);Z=Pt(T,Z);let ct=s.convert(T.format,T.colorSpace),D=s.convert(T.type),$=M(T.internalFormat,ct,D,T.normalized,T.colorSpace,T.isVideoTexture);Jt(nt,T);let q,lt=T.mipmaps,st=T.isVideoTexture!==!0,ot=dt.__version===void 0||Q===!0,At=rt.dataReady,Vt=S(T,Z);if(T.isDepthTexture)$=x(T.format===Li,T.type),ot&&(st?e.texStorage2D(i.TEXTURE_2D,1,$,Z.width,Z.height):e.texImage2D(i.TEXTURE_2D,0,$,Z.width,Z.height,0,ct,D,null));else if(T.isDataTexture)if(lt.length>0){st&&ot&&e.texStorage2D(i.TEXTURE_2D,Vt,$,lt[0].width,lt[0].height);for(let at=0,Tt=lt.length;at<Tt;at++)q=lt[at],st?At&&e.texSubImage2D(i.TEXTURE_2D,at,0,0,q.width,q.height,ct,D,q.data):e.texImage2D(i.TEXTURE_2D,at,$,q.width,q.height,0,ct,D,q.data);T.generateMipmaps=!1}else st?(ot&&e.texStorage2D(i.TEXTURE_2D,Vt,$,Z.width,Z.height),At&&Ve(T,Z,ct,D)):e.texImage2D(i.TEXTURE_2D,0,$,Z.width,Z.height,0,ct,D,Z.data);else if(T.isCompressedTexture)if(T.isCompressedArrayTexture){st&&ot&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Vt,$,lt[0].width,lt[0].height,Z.depth);for(let at=0,Tt=lt.length;at<Tt;at++)if(q=lt[at],T.format!==mn)if(ct!==null)if(st){if(At)if(T.layerUpdates.size>0){let zt=wd(q.width,q.height,T.format,T.type);for(let bt of T.layerUpdates){let se=q.data.subarray(bt*zt/q.data.BYTES_PER_ELEMENT,(bt+1)*zt/q.data.BYTES_PER_ELEMENT);e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,at,0,0,bt,q.width,q.height,1,ct,se)}}else e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,at,0,0,0,q.width,q.height,Z.depth,ct,q.data)}else e.compressedTexImage3D(i.TEXTURE_2D_ARRAY,at,$,q.width,q.height,Z.depth,0,q.data,0,0);else Rt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else st?At&&e.texSubImage3D(i.TEXTURE_2D_ARRAY,at,0,0,0,q.width,q.height,Z.depth,ct,D,q.data):e.texImage3D(i.TEXTURE_2D_ARRAY,at,$,q.width,q.height,Z.depth,0,ct,D,q.data);T.layerUpdates.size>0&&T.clearLayerUpdates()}else{st&&ot&&e.texStorage2D(i.TEXTURE_2D,Vt,$,lt[0].width,lt[0].height);for(let at=0,Tt=lt.length;at<Tt;at++)q=lt[at],T.format!==mn?ct!==null?st?At&&e.compressedTexSubImage2D(i.TEXTURE_2D,at,0,0,q.width,q.height,ct,q.data):e.compressedTexImage2D(i.TEXTURE_2D,at,$,q.width,q.height,0,q.data):Rt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):st?At&&e.texSubImage2D(i.TEXTURE_2D,at,0,0,q.width,q.height,ct,D,q.data):e.texImage2D(i.TEXTURE_2D,at,$,q.width,q.height,0,ct,D,q.data)}else if(T.isDataArrayTexture)if(st){if(ot&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Vt,$,Z.width,Z.height,Z.depth),At)if(T.layerUpdates.size>0){let at=wd(Z.width,Z.height,T.format,T.type);for(let Tt of T.layerUpdates){let zt=Z.data.subarray(Tt*at/Z.data.BYTES_PER_ELEMENT,(Tt+1)*at/Z.data.BYTES_PER_ELEMENT);e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,Tt,Z.width,Z.height,1,ct,D,zt)}T.clearLayerUpdates()}else e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,Z.width,Z.height,Z.depth,ct,D,Z.data)}else e.texImage3D(i.TEXTURE_2D_ARRAY,0,$,Z.width,Z.height,Z.depth,0,ct,D,Z.data);else if(T.isData3DTexture)st?(ot&&e.texStorage3D(i.TEXTURE_3D,Vt,$,Z.width,Z.height,Z.depth),At&&e.texSubImage3D(i.TEXTURE_3D,0,0,0,0,Z.width,Z.height,Z.depth,ct,D,Z.data)):e.texImage3D(i.TEXTURE_3D,0,$,Z.width,Z.height,Z.depth,0,ct,D,Z.data);else if(T.isFramebufferTexture){if(ot)if(st)e.texStorage2D(i.TEXTURE_2D,Vt,$,Z.width,Z.height);else{let at=Z.width,Tt=Z.height;for(let zt=0;zt<Vt;zt++)e.texImage2D(i.TEXTURE_2D,zt,$,at,Tt,0,ct,D,null),at>>=1,Tt>>=1}}else if(T.isHTMLTexture){if("texElementImage2D"in i){let at=i.canvas;if(at.hasAttribute("layoutsubtree")||at.setAttribute("layoutsubtree","true"),Z.parentNode!==at){at.appendChild(Z),u.add(T),at.onpaint=Tt=>{let zt=Tt.changedElements;for(let bt of u)zt.includes(bt.image)&&(bt.needsUpdate=!0)},at.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,Z);else{let zt=i.RGBA,bt=i.RGBA,se=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,zt,bt,se,Z)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(lt.length>0){if(st&&ot){let at=Ot(lt[0]);e.texStorage2D(i.TEXTURE_2D,Vt,$,at.width,at.height)}for(let at=0,Tt=lt.length;at<Tt;at++)q=lt[at],st?At&&e.texSubImage2D(i.TEXTURE_2D,at,0,0,ct,D,q):e.texImage2D(i.TEXTURE_2D,at,$,ct,D,q);T.generateMipmaps=!1}else if(st){if(ot){let at=Ot(Z);e.texStorage2D(i.TEXTURE_2D,Vt,$,at.width,at.height)}At&&e.texSubImage2D(i.TEXTURE_2D,0,0,0,ct,D,Z)}else e.texImage2D(i.TEXTURE_2D,0,$,ct,D,Z);w(T)&&T.mipmapsAutoUpdate===!0&&p(nt),dt.__version=rt.version,T.onUpdate&&T.onUpdate(T)}P.__version=T.version}function yn(P,T,H){if(T.image.length!==6)return;let nt=ce(P,T),Q=T.source;e.bindTexture(i.TEXTURE_CUBE_MAP,P.__webglTexture,i.TEXTURE0+H);let rt=n.get(Q);if(Q.version!==rt.__version||nt===!0){e.activeTexture(i.TEXTURE0+H);let dt=Gt.getPrimaries(Gt.workingColorSpace),J=T.colorSpace===Di?null:Gt.getPrimaries(T.colorSpace),Z=T.colorSpace===Di||dt===J?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),e.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Z);let ct=T.isCompressedTexture||T.image[0].isCompressedTexture,D=T.image[0]&&T.image[0].isDataTexture,$=[];for(let bt=0;bt<6;bt++)!ct&&!D?$[bt]=v(T.image[bt],!0,a.maxCubemapSize):$[bt]=D?T.image[bt].image:T.image[bt],$[bt]=Pt(T,$[bt]);let q=$[0],lt=s.convert(T.format,T.colorSpace),st=s.convert(T.type),ot=M(T.internalFormat,lt,st,T.normalized,T.colorSpace),At=T.isVideoTexture!==!0,Vt=rt.__version===void 0||nt===!0,at=Q.dataReady,Tt=S(T,q);Jt(i.TEXTURE_CUBE_MAP,T);let zt;if(T.isDepthTexture){if(ot=x(T.format===Li,T.type),Vt)if(At)e.texStorage2D(i.TEXTURE_CUBE_MAP,1,ot,q.width,q.height);else for(let bt=0;bt<6;bt++)e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,0,ot,q.width,q.height,0,lt,st,null)}else if(ct){At&&Vt&&e.texStorage2D(i.TEXTURE_CUBE_MAP,Tt,ot,q.width,q.height);for(let bt=0;bt<6;bt++){zt=$[bt].mipmaps;for(let se=0;se<zt.length;se++){let Ue=zt[se];T.format!==mn?lt!==null?At?at&&e.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se,0,0,Ue.width,Ue.height,lt,Ue.data):e.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se,ot,Ue.width,Ue.height,0,Ue.data):Rt("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):At?at&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se,0,0,Ue.width,Ue.height,lt,st,Ue.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se,ot,Ue.width,Ue.height,0,lt,st,Ue.data)}}}else{if(zt=T.mipmaps,At&&Vt){zt.length>0&&Tt++;let bt=Ot($[0]);e.texStorage2D(i.TEXTURE_CUBE_MAP,Tt,ot,bt.width,bt.height)}for(let bt=0;bt<6;bt++)if(D){At?at&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,0,0,0,$[bt].width,$[bt].height,lt,st,$[bt].data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,0,ot,$[bt].width,$[bt].height,0,lt,st,$[bt].data);for(let se=0;se<zt.length;se++){let Bi=zt[se].image[bt].image;At?at&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se+1,0,0,Bi.width,Bi.height,lt,st,Bi.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se+1,ot,Bi.width,Bi.height,0,lt,st,Bi.data)}}else{At?at&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,0,0,0,lt,st,$[bt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,0,ot,lt,st,$[bt]);for(let se=0;se<zt.length;se++){let Ue=zt[se];At?at&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se+1,0,0,lt,st,Ue.image[bt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+bt,se+1,ot,lt,st,Ue.image[bt])}}}w(T)&&T.mipmapsAutoUpdate===!0&&p(i.TEXTURE_CUBE_MAP),rt.__version=Q.version,T.onUpdate&&T.onUpdate(T)}P.__version=T.version}function ge(P,T,H,nt,Q,rt){let dt=s.convert(H.format,H.colorSpace),J=s.convert(H.type),Z=M(H.internalFormat,dt,J,H.normalized,H.colorSpace),ct=n.get(T),D=n.get(H);if(D.__renderTarget=T,!ct.__hasExternalTextures){let $=Math.max(1,T.width>>rt),q=Math.max(1,T.height>>rt);Q===i.TEXTURE_3D||Q===i.TEXTURE_2D_ARRAY?e.texImage3D(Q,rt,Z,$,q,T.depth,0,dt,J,null):e.texImage2D(Q,rt,Z,$,q,0,dt,J,null)}e.bindFramebuffer(i.FRAMEBUFFER,P),mt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,nt,Q,D.__webglTexture,0,me(T)):(Q===i.TEXTURE_2D||Q>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&Q<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,nt,Q,D.__webglTexture,rt),e.bindFramebuffer(i.FRAMEBUFFER,null)}function ei(P,T,H){if(i.bindRenderbuffer(i.RENDERBUFFER,P),T.depthBuffer){let nt=T.depthTexture,Q=nt&&nt.isDepthTexture?nt.type:null,rt=x(T.stencilBuffer,Q),dt=T.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;mt(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,me(T),rt,T.width,T.height):H?i.renderbufferStorageMultisample(i.RENDERBUFFER,me(T),rt,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,rt,T.width,T.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,dt,i.RENDERBUFFER,P)}else{let nt=T.textures;for(let Q=0;Q<nt.length;Q++){let rt=nt[Q],dt=s.convert(rt.format,rt.colorSpace),J=s.convert(rt.type),Z=M(rt.internalFormat,dt,J,rt.normalized,rt.colorSpace);mt(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,me(T),Z,T.width,T.height):H?i.renderbufferStorageMultisample(i.RENDERBUFFER,me(T),Z,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,Z,T.width,T.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function De(P,T,H){let nt=T.isWebGLCubeRenderTarget===!0;if(e.bindFramebuffer(i.FRAMEBUFFER,P),!(T.depthTexture&&T.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let Q=n.get(T.depthTexture);Q.__renderTarget=T;let rt=nt?T.depthTexture.image[0]:T.depthTexture.image;(!Q.__webglTexture||rt.width!==T.width||rt.height!==T.height)&&(rt.width=T.width,rt.height=T.height,T.depthTexture.needsUpdate=!0),nt?pt(T.depthTexture,0):it(T.depthTexture,0);let dt=Q.__webglTexture,J=me(T),Z=nt?i.TEXTURE_CUBE_MAP_POSITIVE_X+H:i.TEXTURE_2D,ct=T.depthTexture.format===Li?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(T.depthTexture.format===Ii)mt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ct,Z,dt,0,J):i.framebufferTexture2D(i.FRAMEBUFFER,ct,Z,dt,0);else if(T.depthTexture.format===Li)mt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ct,Z,dt,0,J):i.framebufferTexture2D(i.FRAMEBUFFER,ct,Z,dt,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function Pn(P){let T=n.get(P),H=P.isWebGLCubeRenderTarget===!0;if(T.__boundDepthTexture!==P.depthTexture){let nt=P.depthTexture;if(T.__depthDisposeCallback&&T.__depthDisposeCallback(),nt){let Q=()=>{delete T.__boundDepthTexture,delete T.__depthDisposeCallback,nt.removeEventListener("dispose",Q)};nt.addEventListener("dispose",Q),T.__depthDisposeCallback=Q}T.__boundDepthTexture=nt}if(P.depthTexture&&!T.__autoAllocateDepthBuffer)if(H)for(let nt=0;nt<6;nt++)De(T.__webglFramebuffer[nt],P,nt);else P.texture.mipmaps.length>0?De(T.__webglFramebuffer[0],P,0):De(T.__webglFramebuffer,P,0);else if(H){T.__webglDepthbuffer=[];for(let nt=0;nt<6;nt++)if(e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[nt]),T.__webglDepthbuffer[nt]===void 0)T.__webglDepthbuffer[nt]=i.createRenderbuffer(),ei(T.__webglDepthbuffer[nt],P,!1);else{let Q=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,rt=T.__webglDepthbuffer[nt];i.bindRenderbuffer(i.RENDERBUFFER,rt),i.framebufferRenderbuffer(i.FRAMEBUFFER,Q,i.RENDERBUFFER,rt)}}else if(P.texture.mipmaps.length>0?e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[0]):e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer),T.__webglDepthbuffer===void 0)T.__webglDepthbuffer=i.createRenderbuffer(),ei(T.__webglDepthbuffer,P,!1);else{let Q=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,rt=T.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,rt),i.framebufferRenderbuffer(i.FRAMEBUFFER,Q,i.RENDERBUFFER,rt)}e.bindFramebuffer(i.FRAMEBUFFER,null)}function Ln(P,T,H){let nt=n.get(P);T!==void 0&&ge(nt.__webglFramebuffer,P,P.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),H!==void 0&&Pn(P)}function Dn(P){let T=P.texture,H=n.get(P),nt=n.get(T);P.addEventListener("dispose",C),E(P);let Q=P.textures,rt=P.isWebGLCubeRenderTarget===!0,dt=Q.length>1;if(dt||(nt.__webglTexture===void 0&&(nt.__webglTexture=i.createTexture()),nt.__version=T.version,r.memory.textures++),rt){H.__webglFramebuffer=[];for(let J=0;J<6;J++)if(T.mipmaps.length>0){H.__webglFramebuffer[J]=[];for(let Z=0;Z<T.mipmaps.length;Z++)H.__webglFramebuffer[J][Z]=i.createFramebuffer()}else H.__webglFramebuffer[J]=i.createFramebuffer()}else{if(T.mipmaps.length>0){H.__webglFramebuffer=[];for(let J=0;J<T.mipmaps.length;J++)H.__webglFramebuffer[J]=i.createFramebuffer()}else H.__webglFramebuffer=i.createFramebuffer();if(dt)for(let J=0,Z=Q.length;J<Z;J++){let ct=n.get(Q[J]);ct.__webglTexture===void 0&&(ct.__webglTexture=i.createTexture(),r.memory.textures++)}if(P.samples>0&&mt(P)===!1){H.__webglMultisampledFramebuffer=i.createFramebuffer(),H.__webglColorRenderbuffer=[],e.bindFramebuffer(i.FRAMEBUFFER,H.__webglMultisampledFramebuffer);for(let J=0;J<Q.length;J++){let Z=Q[J];H.__webglColorRenderbuffer[J]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,H.__webglColorRenderbuffer[J]);let ct=s.convert(Z.format,Z.colorSpace),D=s.convert(Z.type),$=M(Z.internalFormat,ct,D,Z.normalized,Z.colorSpace,P.isXRRenderTarget===!0),q=me(P);i.renderbufferStorageMultisample(i.RENDERBUFFER,q,$,P.width,P.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+J,i.RENDERBUFFER,H.__webglColorRenderbuffer[J])}i.bindRenderbuffer(i.RENDERBUFFER,null),P.depthBuffer&&(H.__webglDepthRenderbuffer=i.createRenderbuffer(),ei(H.__webglDepthRenderbuffer,P,!0)),e.bindFramebuffer(i.FRAMEBUFFER,null)}}if(rt){e.bindTexture(i.TEXTURE_CUBE_MAP,nt.__webglTexture),Jt(i.TEXTURE_CUBE_MAP,T);for(let J=0;J<6;J++)if(T.mipmaps.length>0)for(let Z=0;Z<T.mipmaps.length;Z++)ge(H.__webglFramebuffer[J][Z],P,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+J,Z);else ge(H.__webglFramebuffer[J],P,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+J,0);w(T)?p(i.TEXTURE_CUBE_MAP):T.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,T.mipmaps.length-1),e.unbindTexture()}else if(dt){for(let J=0,Z=Q.length;J<Z;J++){let ct=Q[J],D=n.get(ct),$=i.TEXTURE_2D;(P.isWebGL3DRenderTarget||P.isWebGLArrayRenderTarget)&&($=P.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture($,D.__webglTexture),Jt($,ct),ge(H.__webglFramebuffer,P,ct,i.COLOR_ATTACHMENT0+J,$,0),w(ct)&&p($)}e.unbindTexture()}else{let J=i.TEXTURE_2D;if((P.isWebGL3DRenderTarget||P.isWebGLArrayRenderTarget)&&(J=P.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture(J,nt.__webglTexture),Jt(J,T),T.mipmaps.length>0)for(let Z=0;Z<T.mipmaps.length;Z++)ge(H.__webglFramebuffer[Z],P,T,i.COLOR_ATTACHMENT0,J,Z);else ge(H.__webglFramebuffer,P,T,i.COLOR_ATTACHMENT0,J,0);w(T)?p(J):T.mipmaps.length>0&&i.texParameteri(J,i.TEXTURE_MAX_LEVEL,T.mipmaps.length-1),e.unbindTexture()}P.depthBuffer&&Pn(P)}function k(P){let T=P.textures;for(let H=0,nt=T.length;H<nt;H++){let Q=T[H];if(w(Q)&&Q.mipmapsAutoUpdate===!0){let rt=_(P),dt=n.get(Q).__webglTexture;e.bindTexture(rt,dt),p(rt),e.unbindTexture()}}}let Un=[];function pe(P){if(P.samples>0){if(mt(P)===!1){let T=P.textures,H=P.width,nt=P.height,Q=i.COLOR_BUFFER_BIT,rt=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,dt=n.get(P),J=T.length>1;if(J)for(let ct=0;ct<T.length;ct++)e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ct,i.RENDERBUFFER,null),e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ct,i.TEXTURE_2D,null,0);e.bindFramebuffer(i.READ_FRAMEBUFFER,dt.__webglMultisampledFramebuffer),P.texture.mipmaps.length>0?e.bindFramebuffer(i.DRAW_FRAMEBUFFER,dt.__webglFramebuffer[0]):e.bindFramebuffer(i.DRAW_FRAMEBUFFER,dt.__webglFramebuffer);for(let ct=0;ct<T.length;ct++){if(P.resolveDepthBuffer&&(P.depthBuffer&&(Q|=i.DEPTH_BUFFER_BIT),P.stencilBuffer&&P.resolveStencilBuffer&&(Q|=i.STENCIL_BUFFER_BIT)),J){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,dt.__webglColorRenderbuffer[ct]);let D=n.get(T[ct]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,D,0)}i.blitFramebuffer(0,0,H,nt,0,0,H,nt,Q,i.NEAREST),c===!0&&(Un.length=0,Un.push(i.COLOR_ATTACHMENT0+ct),P.depthBuffer&&P.storeMultisampledDepthBuffer===!1&&Un.push(rt),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Un))}if(e.bindFramebuffer(i.READ_FRAMEBUFFER,null),e.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),J)for(let ct=0;ct<T.length;ct++){e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ct,i.RENDERBUFFER,dt.__webglColorRenderbuffer[ct]);let D=n.get(T[ct]).__webglTexture;e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ct,i.TEXTURE_2D,D,0)}e.bindFramebuffer(i.DRAW_FRAMEBUFFER,dt.__webglMultisampledFramebuffer)}else if(P.depthBuffer&&P.storeMultisampledDepthBuffer===!1&&c){let T=P.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[T])}}}function me(P){return Math.min(a.maxSamples,P.samples)}function mt(P){let T=n.get(P);return P.samples>0&&t.has("WEBGL_multisampled_render_to_texture")===!0&&T.__useRenderToTexture!==!1}function Te(P){let T=r.render.frame;h.get(P)!==T&&(h.set(P,T),P.update())}function Pt(P,T){let H=P.colorSpace,nt=P.format,Q=P.type;return P.isCompressedTexture===!0||P.isVideoTexture===!0||H!==er&&H!==Di&&(Gt.getTransfer(H)===ie?(nt!==mn||Q!==en)&&Rt("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):Lt("WebGLTextures: Unsupported texture color space:",H)),T}function Ot(P){return typeof HTMLImageElement<"u"&&P instanceof HTMLImageElement?(l.width=P.naturalWidth||P.width,l.height=P.naturalHeight||P.height):typeof VideoFrame<"u"&&P instanceof VideoFrame?(l.width=P.displayWidth,l.height=P.displayHeight):(l.width=P.width,l.height=P.height),l}this.allocateTextureUnit=It,this.resetTextureUnits=Y,this.getTextureUnits=tt,this.setTextureUnits=gt,this.setTexture2D=it,this.setTexture2DArray=_t,this.setTexture3D=Et,this.setTextureCube=pt,this.rebindTextures=Ln,this.setupRenderTarget=Dn,this.updateRenderTargetMipmap=k,this.updateMultisampleRenderTarget=pe,this.setupDepthRenderbuffer=Pn,this.setupFrameBufferTexture=ge,this.useMultisampledRTT=mt,this.dispose=U}function jM(i,t){function e(n,a=Di){let s,r=Gt.getTransfer(a);if(n===en)return i.UNSIGNED_BYTE;if(n===Pc)return i.UNSIGNED_SHORT_4_4_4_4;if(n===Lc)return i.UNSIGNED_SHORT_5_5_5_1;if(n===cd)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===ld)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===Dr)return i.BYTE;if(n===Ur)return i.SHORT;if(n===Qi)return i.UNSIGNED_SHORT;if(n===us)return i.INT;if(n===Mn)return i.UNSIGNED_INT;if(n===pn)return i.FLOAT;if(n===Zn)return i.HALF_FLOAT;if(n===hd)return i.ALPHA;if(n===dd)return i.RGB;if(n===mn)return i.RGBA;if(n===Ii)return i.DEPTH_COMPONENT;if(n===Li)return i.DEPTH_STENCIL;if(n===Or)return i.RED;if(n===Aa)return i.RED_INTEGER;if(n===hi)return i.RG;if(n===fs)return i.RG_INTEGER;if(n===ps)return i.RGBA_INTEGER;if(n===Fr||n===Br||n===kr||n===zr)if(r===ie)if(s=t.get("WEBGL_compressed_texture_s3tc_srgb"),s!==null){if(n===Fr)return s.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===Br)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===kr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===zr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(s=t.get("WEBGL_compressed_texture_s3tc"),s!==null){if(n===Fr)return s.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===Br)return s.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===kr)return s.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===zr)return s.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===Dc||n===Uc||n===Oc||n===Fc)if(s=t.get("WEBGL_compressed_texture_pvrtc"),s!==null){if(n===Dc)return s.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===Uc)return s.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===Oc)return s.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===Fc)return s.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===Bc||n===kc||n===zc||n===Vc||n===Hc||n===Vr||n===Gc)if(s=t.get("WEBGL_compressed_texture_etc"),s!==null){if(n===Bc||n===kc)return r===ie?s.COMPRESSED_SRGB8_ETC2:s.COMPRESSED_RGB8_ETC2;if(n===zc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:s.COMPRESSED_RGBA8_ETC2_EAC;if(n===Vc)return s.COMPRESSED_R11_EAC;if(n===Hc)return s.COMPRESSED_SIGNED_R11_EAC;if(n===Vr)return s.COMPRESSED_RG11_EAC;if(n===Gc)return s.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===Wc||n===jc||n===Xc||n===qc||n===Yc||n===Jc||n===Kc||n===Zc||n===$c||n===Qc||n===tl||n===el||n===nl||n===il)if(s=t.get("WEBGL_compressed_texture_astc"),s!==null){if(n===Wc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:s.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===jc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:s.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===Xc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:s.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===qc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:s.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===Yc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:s.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===Jc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:s.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===Kc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:s.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===Zc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:s.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===$c)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:s.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===Qc)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:s.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===tl)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:s.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===el)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:s.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===nl)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:s.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===il)return r===ie?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:s.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===al||n===sl||n===rl)if(s=t.get("EXT_texture_compression_bptc"),s!==null){if(n===al)return r===ie?s.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:s.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===sl)return s.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===rl)return s.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===ol||n===cl||n===Hr||n===ll)if(s=t.get("EXT_texture_compression_rgtc"),s!==null){if(n===ol)return s.COMPRESSED_RED_RGTC1_EXT;if(n===cl)return s.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Hr)return s.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===ll)return s.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===wa?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:e}}function JM(i,t){function e(g,b){g.matrixAutoUpdate===!0&&g.updateMatrix(),b.value.copy(g.matrix)}function n(g,b){b.color.getRGB(g.fogColor.value,vd(i)),b.isFog?(g.fogNear.value=b.near,g.fogFar.value=b.far):b.isFogExp2&&(g.fogDensity.value=b.density)}function a(g,b,v,w,p){b.isNodeMaterial?b.uniformsNeedUpdate=!1:b.isMeshBasicMaterial?s(g,b):b.isMeshLambertMaterial?(s(g,b),b.envMap&&(g.envMapIntensity.value=b.envMapIntensity)):b.isMeshToonMaterial?(s(g,b),u(g,b)):b.isMeshPhongMaterial?(s(g,b),h(g,b),b.envMap&&(g.envMapIntensity.value=b.envMapIntensity)):b.isMeshStandardMaterial?(s(g,b),d(g,b),b.isMeshPhysicalMaterial&&f(g,b,p)):b.isMeshMatcapMaterial?(s(g,b),m(g,b)):b.isMeshDepthMaterial?s(g,b):b.isMeshDistanceMaterial?(s(g,b),y(g,b)):b.isMeshNormalMaterial?s(g,b):b.isLineBasicMaterial?(r(g,b),b.isLineDashedMaterial&&o(g,b)):b.isPointsMaterial?c(g,b,v,w):b.isSpriteMaterial?l(g,b):b.isShadowMaterial?(g.color.value.copy(b.color),g.opacity.value=b.opacity):b.isShaderMaterial&&(b.uniformsNeedUpdate=!1)}function s(g,b){g.opacity.value=b.opacity,b.color&&g.diffuse.value.copy(b.color),b.emissive&&g.emissive.value.copy(b.emissive).multiplyScalar(b.emissiveIntensity),b.map&&(g.map.value=b.map,e(b.map,g.mapTransform)),b.alphaMap&&(g.alphaMap.value=b.alphaMap,e(b.alphaMap,g.alphaMapTransform)),b.bumpMap&&(g.bumpMap.value=b.bumpMap,e(b.bumpMap,g.bumpMapTransform),g.bumpScale.value=b.bumpScale,b.side===Ge&&(g.bumpScale.value*=-1)),b.normalMap&&(g.normalMap.value=b.normalMap,e(b.normalMap,g.normalMapTransform),g.normalScale.value.copy(b.normalScale),b.side===Ge&&g.normalScale.value.negate()),b.displacementMap&&(g.displacementMap.value=b.displacementMap,e(b.displacementMap,g.displacementMapTransform),g.displacementScale.value=b.displacementScale,g.displacementBias.value=b.displacementBias),b.emissiveMap&&(g.emissiveMap.value=b.emissiveMap,e(b.emissiveMap,g.emissiveMapTransform)),b.specularMap&&(g.specularMap.value=b.specularMap,e(b.specularMap,g.specularMapTransform)),b.alphaTest>0&&(g.alphaTest.value=b.alphaTest);let v=t.get(b),w=v.envMap,p=v.envMapRotation;w&&(g.envMap.value=w,g.envMapRotation.value.setFromMatrix4(YM.makeRotationFromEuler(p)).transpose(),w.isCubeTexture&&w.isRenderTargetTexture===!1&&g.envMapRotation.value.premultiply(bm),g.reflectivity.value=b.reflectivity,g.ior.value=b.ior,g.refractionRatio.value=b.refractionRatio),b.lightMap&&(g.lightMap.value=b.lightMap,g.lightMapIntensity.value=b.lightMapIntensity,e(b.lightMap,g.lightMapTransform)),b.aoMap&&(g.aoMap.value=b.aoMap,g.aoMapIntensity.value=b.aoMapIntensity,e(b.aoMap,g.aoMapTransform))}function r(g,b){g.diffuse.value.copy(b.color),g.opacity.value=b.opacity,b.map&&(g.map.value=b.map,e(b.map,g.mapTransform))}function o(g,b){g.dashSize.value=b.dashSize,g.totalSize.value=b.dashSize+b.gapSize,g.scale.value=b.scale}function c(g,b,v,w){g.diffuse.value.copy(b.color),g.opacity.value=b.opacity,g.size.value=b.size*v,g.scale.value=w*.5,b.map&&(g.map.value=b.map,e(b.map,g.uvTransform)),b.alphaMap&&(g.alphaMap.value=b.alphaMap,e(b.alphaMap,g.alphaMapTransform)),b.alphaTest>0&&(g.alphaTest.value=b.alphaTest)}function l(g,b){g.diffuse.value.copy(b.color),g.opacity.value=b.opacity,g.rotation.value=b.rotation,b.map&&(g.map.value=b.map,e(b.map,g.mapTransform)),b.alphaMap&&(g.alphaMap.value=b.alphaMap,e(b.alphaMap,g.alphaMapTransform)),b.alphaTest>0&&(g.alphaTest.value=b.alphaTest)}function h(g,b){g.specular.value.copy(b.specular),g.shininess.value=Math.max(b.shininess,1e-4)}function u(g,b){b.gradientMap&&(g.gradientMap.value=b.gradientMap)}function d(g,b){g.metalness.value=b.metalness,b.metalnessMap&&(g.metalnessMap.value=b.metalnessMap,e(b.metalnessMap,g.metalnessMapTransform)),g.roughness.value=b.roughness,b.roughnessMap&&(g.roughnessMap.value=b.roughnessMap,e(b.roughnessMap,g.roughnessMapTransform)),b.envMap&&(g.envMapIntensity.value=b.envMapIntensity)}function f(g,b,v){g.ior.value=b.ior,b.diffuseRoughness>0&&(g.diffuseRoughness.value=b.diffuseRoughness,b.diffuseRoughnessMap&&(g.diffuseRoughnessMap.value=b.diffuseRoughnessMap,e(b.diffuseRoughnessMap,g.diffuseRoughnessMapTransform))),b.sheen>0&&(g.sheenColor.value.copy(b.sheenColor).multiplyScalar(b.sheen),g.sheenRoughness.value=b.sheenRoughness,b.sheenColorMap&&(g.sheenColorMap.value=b.sheenColorMap,e(b.sheenColorMap,g.sheenColorMapTransform)),b.sheenRoughnessMap&&(g.sheenRoughnessMap.value=b.sheenRoughnessMap,e(b.sheenRoughnessMap,g.sheenRoughnessMapTransform))),b.clearcoat>0&&(g.clearcoat.value=b.clearcoat,g.clearcoatRoughness.value=b.clearcoatRoughness,b.clearcoatMap&&(g.clearcoatMap.value=b.clearcoatMap,e(b.clearcoatMap,g.clearcoatMapTransform)),b.clearcoatRoughnessMap&&(g.clearcoatRoughnessMap.value=b.clearcoatRoughnessMap,e(b.clearcoatRoughnessMap,g.clearcoatRoughnessMapTransform)),b.clearcoatNormalMap&&(g.clearcoatNormalMap.value=b.clearcoatNormalMap,e(b.clearcoatNormalMap,g.clearcoatNormalMapTransform),g.clearcoatNormalScale.value.copy(b.clearcoatNormalScale),b.side===Ge&&g.clearcoatNormalScale.value.negate())),b.dispersion>0&&(g.dispersion.value=b.dispersion),b.retroreflectivity>0&&(g.retroreflectivity.value=b.retroreflectivity),b.iridescence>0&&(g.iridescence.value=b.iridescence,g.iridescenceIOR.value=b.iridescenceIOR,g.iridescenceThicknessMinimum.value=b.iridescenceThicknessMinimum,g.iridescenceThicknessMaximum.value=b.iridescenceThicknessMaximum,b.iridescenceMap&&(g.iridescenceMap.value=b.iridescenceMap,e(b.iridescenceMap,g.iridescenceMapTransform)),b.iridescenceThicknessMap&&(g.iridescenceThicknessMap.value=b.iridescenceThicknessMap,e(b.iridescenceThicknessMap,g.iridescenceThicknessMapTransform))),b.transmission>0&&(g.transmission.value=b.transmission,g.transmissionSamplerMap.value=v.texture,g.transmissionSamplerSize.value.set(v.width,v.height),b.transmissionMap&&(g.transmissionMap.value=b.transmissionMap,e(b.transmissionMap,g.transmissionMapTransform)),g.thickness.value=b.thickness,b.thicknessMap&&(g.thicknessMap.value=b.thicknessMap,e(b.thicknessMap,g.thicknessMapTransform)),g.attenuationDistance.value=b.attenuationDistance,g.attenuationColor.value.copy(b.attenuationColor)),b.anisotropy>0&&(g.anisotropyVector.value.set(b.anisotropy*Math.cos(b.anisotropyRotation),b.anisotropy*Math.sin(b.anisotropyRotation)),b.anisotropyMap&&(g.anisotropyMap.value=b.anisotropyMap,e(b.anisotropyMap,g.anisotropyMapTransform))),g.specularIntensity.value=b.specularIntensity,g.specularColor.value.copy(b.specularColor),b.specularColorMap&&(g.specularColorMap.value=b.specularColorMap,e(b.specularColorMap,g.specularColorMapTransform)),b.specularIntensityMap&&(g.specularIntensityMap.value=b.specularIntensityMap,e(b.specularIntensityMap,g.specularIntensityMapTransform))}function m(g,b){b.matcap&&(g.matcap.value=b.matcap)}function y(g,b){let v=t.get(b).light;g.referencePosition.value.setFromMatrixPosition(v.matrixWorld),g.nearDistance.value=v.shadow.camera.near,g.farDistance.value=v.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:a}}function KM(i,t,e,n){let a={},s={};function r(v,w){let p=w.program;n.uniformBlockBinding(v,p,a[v.id])}function o(v,w){let p=a[v.id];p===void 0&&(m(v),p=c(v),a[v.id]=p,v.addEventListener("dispose",g));let _=w.program;n.updateUBOMapping(v,_);let M=t.render.frame;s[v.id]!==M&&(l(v),s[v.id]=M)}function c(v){let w=i.createBuffer(),p=v.__size,_=v.usage;return i.bindBuffer(i.UNIFORM_BUFFER,w),i.bufferData(i.UNIFORM_BUFFER,p,_),i.bindBuffer(i.UNIFORM_BUFFER,null),w}function l(v){let w=a[v.id],p=v.uniforms,_=v.__cache;i.bindBuffer(i.UNIFORM_BUFFER,w);for(let M=0,x=p.length;M<x;M++){let S=p[M];if(Array.isArray(S))for(let E=0,A=S.length;E<A;E++)h(S[E],M,E,_);else h(S,M,0,_)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(v,w,p,_){if(d(v,w,p,_)===!0){let M=v.__offset,x=v.value;if(Array.isArray(x)){let S=0;for(let E=0;E<x.length;E++){let A=x[E],R=y(A,!0);u(A,v.__data,S),S+=R.storage/Float32Array.BYTES_PER_ELEMENT}}else u(x,v.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,M,v.__data)}}function u(v,w,p){typeof v=="number"||typeof v=="boolean"?w[p]=v:v.isMatrix3?(w[p]=v.elements[0],w[p+1]=v.elements[1],w[p+2]=v.elements[2],w[p+3]=0,w[p+4]=v.elements[3],w[p+5]=v.elements[4],w[p+6]=v.elements[5],w[p+7]=0,w[p+8]=v.elements[6],w[p+9]=v.elements[7],w[p+10]=v.elements[8],w[p+11]=0):ArrayBuffer.isView(v)?w.set(v.subarray(0,w.length-p),p):v.toArray(w,p)}function d(v,w,p,_){let M=v.value,x=w+"_"+p;if(Array.isArray(M)){_[x]===void 0&&(_[x]=[]);let S=_[x],E=!1;for(let A=0;A<M.length;A++)f(M[A],S,A)===!0&&(E=!0);return E}return f(M,_,x)}function f(v,w,p){if(w[p]===void 0)return typeof v=="number"||typeof v=="boolean"?w[p]=v:ArrayBuffer.isView(v)?w[p]=v.slice():w[p]=v.clone(),!0;{let _=w[p];if(typeof v=="number"||typeof v=="boolean"){if(_!==v)return w[p]=v,!0}else{if(ArrayBuffer.isView(v))return!0;if(_.equals(v)===!1)return _.copy(v),!0}}return!1}function m(v){let w=v.uniforms,p=0,_=16;for(let x=0,S=w.length;x<S;x++){let E=Array.isArray(w[x])?w[x]:[w[x]];for(let A=0,R=E.length;A<R;A++){let C=E[A],L=Array.isArray(C.value)?C.value:[C.value],N=Array.isArray(w[x])||Array.isArray(C.value),U=p;for(let B=0,K=L.length;B<K;B++){let W=L[B],Y=y(W,N),tt=p%_,gt=tt%Y.boundary,It=tt+gt;p+=gt,It!==0&&_-It<Y.storage&&(p+=_-It),B===0&&(U=p),p+=Y.storage}let z=C.type==="int"?Int32Array:C.type==="uint"?Uint32Array:Float32Array;C.__data=new z((p-U)/Float32Array.BYTES_PER_ELEMENT),C.__offset=U}}let M=p%_;return M>0&&(p+=_-M),v.__size=p,v.__cache={},this}function y(v,w){let p={boundary:0,storage:0};return typeof v=="number"||typeof v=="boolean"?(p.boundary=4,p.storage=4):v.isVector2?(p.boundary=8,p.storage=8):v.isVector3||v.isColor?(p.boundary=16,p.storage=12):v.isVector4?(p.boundary=16,p.storage=16):v.isMatrix3?(p.boundary=16,p.storage=48):v.isMatrix4?(p.boundary=16,p.storage=64):v.isTexture?Rt("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(v)?(p.boundary=16,p.storage=v.byteLength):Rt("WebGLRenderer: Unsupported uniform value type.",v),w===!0&&(p.boundary=16,p.storage=Math.ceil(p.storage/16)*16),p}function g(v){let w=v.target;w.removeEventListener("dispose",g),i.deleteBuffer(a[w.id]),delete a[w.id],delete s[w.id]}function b(){for(let v in a)i.deleteBuffer(a[v]);a={},s={}}return{bind:r,update:o,dispose:b}}function $M(){return di===null&&(di=new Ti(ZM,16,16,hi,Zn),di.name="DFG_LUT",di.minFilter=fn,di.magFilter=fn,di.wrapS=si,di.wrapT=si,di.generateMipmaps=!1,di.needsUpdate=!0),di}var m0,g0,b0,x0,y0,_0,v0,M0,S0,w0,A0,E0,T0,I0,R0,C0,N0,P0,L0,D0,U0,O0,F0,B0,k0,z0,V0,H0,G0,W0,j0,X0,q0,Y0,J0,K0,Z0,$0,Q0,ty,ey,ny,iy,ay,sy,ry,oy,cy,ly,hy,dy,uy,fy,py,my,gy,by,xy,yy,_y,vy,My,Sy,wy,Ay,Ey,Ty,Iy,Ry,Cy,Ny,Py,Ly,Dy,Uy,Oy,Fy,By,ky,zy,Vy,Hy,Gy,Wy,jy,Xy,qy,Yy,Jy,Ky,Zy,$y,Qy,t_,e_,n_,i_,a_,s_,r_,o_,c_,l_,h_,d_,u_,f_,p_,m_,g_,b_,x_,y_,__,v_,M_,S_,w_,A_,E_,T_,I_,R_,C_,N_,P_,L_,D_,U_,O_,F_,B_,k_,z_,V_,H_,G_,W_,j_,X_,q_,Ht,ft,gn,ul,Y_,cm,Xr,zp,tv,ev,lm,hm,nv,iv,av,pl,mv,dm,um,fm,pm,mm,gm,Wp,jp,Xp,qp,Yp,Ld,Dd,Ud,Nd,ms,aM,sM,Zp,lM,fl,mM,bM,yM,vM,SM,EM,Fd,Bd,DM,BM,kM,zM,VM,rm,Wr,Pd,XM,qM,kd,zd,YM,bm,ZM,di,ml,bs=ua(()=>{Cd();Cd();m0=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,g0=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,b0=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,x0=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,y0=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,_0=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,v0=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,M0=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,S0=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,w0=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,A0=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,E0=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,T0=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,I0=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,R0=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,C0=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,N0=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,P0=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,L0=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,D0=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,U0=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,O0=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,F0=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,B0=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,k0=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,z0=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,V0=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,H0=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,G0=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,W0="gl_FragColor = linearToOutputTexel( gl_FragColor );",j0=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,X0=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,q0=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,Y0=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,J0=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,K0=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,Z0=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,$0=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,Q0=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,ty=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,ey=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,ny=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,iy=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,ay=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,sy=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,ry=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,oy=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,cy=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,ly=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,hy=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,dy=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,uy=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,fy=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,py=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,my=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,gy=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,by=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,xy=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,yy=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,_y=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,vy=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,My=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,Sy=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,wy=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Ay=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Ey=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,Ty=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,Iy=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,Ry=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Cy=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,Ny=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Py=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,Ly=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,Dy=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Uy=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Oy=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,Fy=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,By=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,ky=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,zy=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,Vy=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,Hy=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,Gy=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,Wy=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,jy=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,Xy=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,qy=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,Yy=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,Jy=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,Ky=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,Zy=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,$y=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,Qy=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,t_=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,e_=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,n_=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,i_=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,a_=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,s_=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,r_=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,o_=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,c_=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,l_=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,h_=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,d_=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,u_=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,f_=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,p_=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,m_=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,g_=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,b_=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,x_=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,y_=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,__=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,v_=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,M_=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,S_=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,w_=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,A_=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,E_=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,T_=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,I_=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,R_=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,C_=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,N_=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,P_=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,L_=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,D_=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,U_=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,O_=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,F_=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,B_=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,k_=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,z_=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,V_=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,H_=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,G_=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,W_=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,j_=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,X_=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,q_=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,Ht={alphahash_fragment:m0,alphahash_pars_fragment:g0,alphamap_fragment:b0,alphamap_pars_fragment:x0,alphatest_fragment:y0,alphatest_pars_fragment:_0,aomap_fragment:v0,aomap_pars_fragment:M0,batching_pars_vertex:S0,batching_vertex:w0,begin_vertex:A0,beginnormal_vertex:E0,bsdfs:T0,iridescence_fragment:I0,bumpmap_pars_fragment:R0,clipping_planes_fragment:C0,clipping_planes_pars_fragment:N0,clipping_planes_pars_vertex:P0,clipping_planes_vertex:L0,color_fragment:D0,color_pars_fragment:U0,color_pars_vertex:O0,color_vertex:F0,common:B0,defaultnormal_vertex:k0,displacementmap_pars_vertex:z0,displacementmap_vertex:V0,emissivemap_fragment:H0,emissivemap_pars_fragment:G0,colorspace_fragment:W0,colorspace_pars_fragment:j0,envmap_fragment:X0,envmap_common_pars_fragment:q0,envmap_pars_fragment:Y0,envmap_pars_vertex:J0,envmap_physical_pars_fragment:ry,envmap_vertex:K0,fog_vertex:Z0,fog_pars_vertex:$0,fog_fragment:Q0,fog_pars_fragment:ty,gradientmap_pars_fragment:ey,lightmap_pars_fragment:ny,lights_lambert_fragment:iy,lights_lambert_pars_fragment:ay,lights_pars_begin:sy,lights_toon_fragment:oy,lights_toon_pars_fragment:cy,lights_phong_fragment:ly,lights_phong_pars_fragment:hy,lights_physical_fragment:dy,lights_physical_pars_fragment:uy,lights_fragment_begin:fy,lights_fragment_maps:py,lights_fragment_end:my,lightprobes_pars_fragment:gy,logdepthbuf_fragment:by,logdepthbuf_pars_fragment:xy,logdepthbuf_pars_vertex:yy,logdepthbuf_vertex:_y,map_fragment:vy,map_pars_fragment:My,map_particle_fragment:Sy,map_particle_pars_fragment:wy,metalnessmap_fragment:Ay,metalnessmap_pars_fragment:Ey,morphinstance_vertex:Ty,morphcolor_vertex:Iy,morphnormal_vertex:Ry,morphtarget_pars_vertex:Cy,morphtarget_vertex:Ny,normal_fragment_begin:Py,normal_fragment_maps:Ly,normal_pars_fragment:Dy,normal_pars_vertex:Uy,normal_vertex:Oy,normalmap_pars_fragment:Fy,clearcoat_normal_fragment_begin:By,clearcoat_normal_fragment_maps:ky,clearcoat_pars_fragment:zy,iridescence_pars_fragment:Vy,opaque_fragment:Hy,packing:Gy,premultiplied_alpha_fragment:Wy,project_vertex:jy,dithering_fragment:Xy,dithering_pars_fragment:qy,roughnessmap_fragment:Yy,roughnessmap_pars_fragment:Jy,shadowmap_pars_fragment:Ky,shadowmap_pars_vertex:Zy,shadowmap_vertex:$y,shadowmask_pars_fragment:Qy,skinbase_vertex:t_,skinning_pars_vertex:e_,skinning_vertex:n_,skinnormal_vertex:i_,specularmap_fragment:a_,specularmap_pars_fragment:s_,tonemapping_fragment:r_,tonemapping_pars_fragment:o_,transmission_fragment:c_,transmission_pars_fragment:l_,uv_pars_fragment:h_,uv_pars_vertex:d_,uv_vertex:u_,worldpos_vertex:f_,background_vert:p_,background_frag:m_,backgroundCube_vert:g_,backgroundCube_frag:b_,cube_vert:x_,cube_frag:y_,depth_vert:__,depth_frag:v_,distance_vert:M_,distance_frag:S_,equirect_vert:w_,equirect_frag:A_,linedashed_vert:E_,linedashed_frag:T_,meshbasic_vert:I_,meshbasic_frag:R_,meshlambert_vert:C_,meshlambert_frag:N_,meshmatcap_vert:P_,meshmatcap_frag:L_,meshnormal_vert:D_,meshnormal_frag:U_,meshphong_vert:O_,meshphong_frag:F_,meshphysical_vert:B_,meshphysical_frag:k_,meshtoon_vert:z_,meshtoon_frag:V_,points_vert:H_,points_frag:G_,shadow_vert:W_,shadow_frag:j_,sprite_vert:X_,sprite_frag:q_},ft={common:{diffuse:{value:new kt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new Dt},alphaMap:{value:null},alphaMapTransform:{value:new Dt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new Dt}},envmap:{envMap:{value:null},envMapRotation:{value:new Dt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new Dt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new Dt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new Dt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new Dt},normalScale:{value:new Ct(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new Dt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new Dt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new Dt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new Dt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new kt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new kt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new Dt},alphaTest:{value:0},uvTransform:{value:new Dt}},sprite:{diffuse:{value:new kt(16777215)},opacity:{value:1},center:{value:new Ct(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new Dt},alphaMap:{value:null},alphaMapTransform:{value:new Dt},alphaTest:{value:0}}},gn={basic:{uniforms:nn([ft.common,ft.specularmap,ft.envmap,ft.aomap,ft.lightmap,ft.fog]),vertexShader:Ht.meshbasic_vert,fragmentShader:Ht.meshbasic_frag},lambert:{uniforms:nn([ft.common,ft.specularmap,ft.envmap,ft.aomap,ft.lightmap,ft.emissivemap,ft.bumpmap,ft.normalmap,ft.displacementmap,ft.fog,ft.lights,{emissive:{value:new kt(0)},envMapIntensity:{value:1}}]),vertexShader:Ht.meshlambert_vert,fragmentShader:Ht.meshlambert_frag},phong:{uniforms:nn([ft.common,ft.specularmap,ft.envmap,ft.aomap,ft.lightmap,ft.emissivemap,ft.bumpmap,ft.normalmap,ft.displacementmap,ft.fog,ft.lights,{emissive:{value:new kt(0)},specular:{value:new kt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:Ht.meshphong_vert,fragmentShader:Ht.meshphong_frag},standard:{uniforms:nn([ft.common,ft.envmap,ft.aomap,ft.lightmap,ft.emissivemap,ft.bumpmap,ft.normalmap,ft.displacementmap,ft.roughnessmap,ft.metalnessmap,ft.fog,ft.lights,{emissive:{value:new kt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:Ht.meshphysical_vert,fragmentShader:Ht.meshphysical_frag},toon:{uniforms:nn([ft.common,ft.aomap,ft.lightmap,ft.emissivemap,ft.bumpmap,ft.normalmap,ft.displacementmap,ft.gradientmap,ft.fog,ft.lights,{emissive:{value:new kt(0)}}]),vertexShader:Ht.meshtoon_vert,fragmentShader:Ht.meshtoon_frag},matcap:{uniforms:nn([ft.common,ft.bumpmap,ft.normalmap,ft.displacementmap,ft.fog,{matcap:{value:null}}]),vertexShader:Ht.meshmatcap_vert,fragmentShader:Ht.meshmatcap_frag},points:{uniforms:nn([ft.points,ft.fog]),vertexShader:Ht.points_vert,fragmentShader:Ht.points_frag},dashed:{uniforms:nn([ft.common,ft.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:Ht.linedashed_vert,fragmentShader:Ht.linedashed_frag},depth:{uniforms:nn([ft.common,ft.displacementmap]),vertexShader:Ht.depth_vert,fragmentShader:Ht.depth_frag},normal:{uniforms:nn([ft.common,ft.bumpmap,ft.normalmap,ft.displacementmap,{opacity:{value:1}}]),vertexShader:Ht.meshnormal_vert,fragmentShader:Ht.meshnormal_frag},sprite:{uniforms:nn([ft.sprite,ft.fog]),vertexShader:Ht.sprite_vert,fragmentShader:Ht.sprite_frag},background:{uniforms:{uvTransform:{value:new Dt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:Ht.background_vert,fragmentShader:Ht.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new Dt}},vertexShader:Ht.backgroundCube_vert,fragmentShader:Ht.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:Ht.cube_vert,fragmentShader:Ht.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:Ht.equirect_vert,fragmentShader:Ht.equirect_frag},distance:{uniforms:nn([ft.common,ft.displacementmap,{referencePosition:{value:new F},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:Ht.distance_vert,fragmentShader:Ht.distance_frag},shadow:{uniforms:nn([ft.lights,ft.fog,{color:{value:new kt(0)},opacity:{value:1}}]),vertexShader:Ht.shadow_vert,fragmentShader:Ht.shadow_frag}};gn.physical={uniforms:nn([gn.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new Dt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new Dt},clearcoatNormalScale:{value:new Ct(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new Dt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new Dt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new Dt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new Dt},sheen:{value:0},sheenColor:{value:new kt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new Dt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new Dt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new Dt},transmissionSamplerSize:{value:new Ct},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new Dt},attenuationDistance:{value:0},attenuationColor:{value:new kt(0)},specularColor:{value:new kt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new Dt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new Dt},anisotropyVector:{value:new Ct},anisotropyMap:{value:null},anisotropyMapTransform:{value:new Dt}}]),vertexShader:Ht.meshphysical_vert,fragmentShader:Ht.meshphysical_frag};ul={r:0,b:0,g:0},Y_=new Zt,cm=new Dt;cm.set(-1,0,0,0,1,0,0,0,1);Xr=class extends In{constructor(t=1,e={}){super(t,t,e),this.isWebGLCubeRenderTarget=!0;let n={width:t,height:t,depth:1},a=[n,n,n,n,n,n];this.texture=new fr(a),this._setTextureOptions(e),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(t,e){this.texture.type=e.type,this.texture.colorSpace=e.colorSpace,this.texture.generateMipmaps=e.generateMipmaps,this.texture.minFilter=e.minFilter,this.texture.magFilter=e.magFilter;let n={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},a=new ss(5,5,5),s=new Bn({name:"CubemapFromEquirect",uniforms:Ta(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Ge,blending:va});s.uniforms.tEquirect.value=e;let r=new tn(a,s),o=e.minFilter;return e.minFilter===Pi&&(e.minFilter=fn),new os(1,10,this).update(t,r),e.minFilter=o,r.geometry.dispose(),r.material.dispose(),this}clear(t,e=!0,n=!0,a=!0){let s=t.getRenderTarget();for(let r=0;r<6;r++)t.setRenderTarget(this,r),t.clear(e,n,a);t.setRenderTarget(s)}},zp=256,tv=3,ev=20,lm=256,hm=16,nv=3,iv=new F,av=new kt,pl=class i{constructor(t){this._renderer=t,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new os(1,10,null),this._boxMesh=new tn(new ss(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(t,e=0,n=.1,a=100,s={}){let{size:r=256,position:o=iv}=s,c=this._renderer;this._setSize(r);let l=this._allocateTarget(),h=this._getSourceTarget(!0);e>0&&(h.texture.mipmapsAutoUpdate=!1);let u=c.autoClear,d=c.autoClearColor,f=c.autoClearDepth,m=c.autoClearStencil,y=t.background;c.autoClear=!0,c.autoClearColor=!0,c.autoClearDepth=!0,c.autoClearStencil=!0,y===null&&(t.background=c.getClearColor(av));let g=new os(n,a,h);return g.position.copy(o),g.update(c,t),c.autoClear=u,c.autoClearColor=d,c.autoClearDepth=f,c.autoClearStencil=m,t.background=y,e>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(l,e)),this._applyPMREM(l),l}fromEquirectangular(t,e=null){return this._fromTexture(t,e)}fromCubemap(t,e=null){return this._fromTexture(t,e)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Gp(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Hp(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(t,e){return e>0?1-Math.sqrt(1-t/e):0}_setSize(t){this._cubeSize=Math.max(zp,xd(t))}_fromTexture(t,e){t.mapping===Sa||t.mapping===ds?this._setSize(t.image.length===0?zp:t.image[0].width||t.image[0].image.width):this._setSize(t.image.width/4);let n=e||this._allocateTarget();return this._textureToCubemap(t),this._applyPMREM(n),n}_allocateTarget(){let t=this._cubeSize,e=Vp(t,!1,!1),n=Math.log2(t)-tv;for(let a=0;a<=n;a++)e.texture.mipmaps.push({width:t>>a,height:t>>a});return e.texture.name="PMREM",e.texture.isPMREMTexture=!0,e}_getSourceTarget(t=!1){let e=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==e||t&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Vp(e,!0,t)),this._sourceTarget}_compileMaterial(t){this._boxMesh.material=t,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(t,e,n){let a=this._boxMesh,s=this._cubeCamera;a.material=n,s.renderTarget=t,s.activeMipmapLevel=e;let r=t.width>>e;t.viewport.set(0,0,r,r),s.update(this._renderer,a),t.viewport.set(0,0,t.width,t.height)}_textureToCubemap(t){let e;t.mapping===Sa||t.mapping===ds?(this._cubemapMaterial===null&&(this._cubemapMaterial=Gp()),e=this._cubemapMaterial,e.uniforms.flipEnvMap.value=t.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Hp()),e=this._equirectMaterial),e.uniforms.envMap.value=t,this._renderCube(this._getSourceTarget(),0,e)}_applyPMREM(t){this._ggxMaterial===null&&(this._ggxMaterial=sv(),this._integrationMaterial=rv());let e=this._cubeSize,n=t.texture.mipmaps.length-1,a=this._ggxMaterial.uniforms;a.envMap.value=this._sourceTarget.texture;let s=this._integrationMaterial.uniforms;s.envMap.value=this._sourceTarget.texture,s.sourceLod.value=Math.log2(e/hm);for(let r=0;r<=n;r++){let o=i.lodToRoughness(r,n);if(r>n-nv)s.roughness.value=o,this._renderCube(t,r,this._integrationMaterial);else{let c=o>0?Math.log2(e)+.5*Math.log2(6/(lm*Math.pow(o,4)))+.5:0;a.roughness.value=o,a.lodBias.value=c,this._renderCube(t,r,this._ggxMaterial)}}}_blur(t,e){this._blurMaterial===null&&(this._blurMaterial=ov());let n=this._blurMaterial,a=n.uniforms,s=this._sourceTarget;a.sigma.value=Math.min(e,Math.PI)/Math.SQRT2,a.envMap.value=s.texture,this._renderCube(t,0,n),a.envMap.value=t.texture,this._renderCube(s,0,n)}};mv={[td]:"LINEAR_TONE_MAPPING",[ed]:"REINHARD_TONE_MAPPING",[nd]:"CINEON_TONE_MAPPING",[id]:"ACES_FILMIC_TONE_MAPPING",[sd]:"AGX_TONE_MAPPING",[rd]:"NEUTRAL_TONE_MAPPING",[ad]:"CUSTOM_TONE_MAPPING"};dm=new vn,um=new Ni(1,1),fm=new pr(1),pm=new sr,mm=new rc,gm=new fr,Wp=[],jp=[],Xp=new Float32Array(16),qp=new Float32Array(9),Yp=new Float32Array(4);Ld=class{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.setValue=Ov(e.type)}},Dd=class{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.size=e.size,this.setValue=nM(e.type)}},Ud=class{constructor(t){this.id=t,this.seq=[],this.map={}}setValue(t,e,n){let a=this.seq;for(let s=0,r=a.length;s!==r;++s){let o=a[s];o.setValue(t,e[o.id],n)}}},Nd=/(\w+)(\])?(\[|\.)?/g;ms=class{constructor(t,e){this.seq=[],this.map={};let n=t.getProgramParameter(e,t.ACTIVE_UNIFORMS);for(let r=0;r<n;++r){let o=t.getActiveUniform(e,r),c=t.getUniformLocation(e,o.name);iM(o,c,this)}let a=[],s=[];for(let r of this.seq)r.type===t.SAMPLER_2D_SHADOW||r.type===t.SAMPLER_CUBE_SHADOW||r.type===t.SAMPLER_2D_ARRAY_SHADOW?a.push(r):s.push(r);a.length>0&&(this.seq=a.concat(s))}setValue(t,e,n,a){let s=this.map[e];s!==void 0&&s.setValue(t,n,a)}setOptional(t,e,n){let a=e[n];a!==void 0&&this.setValue(t,n,a)}static upload(t,e,n,a){for(let s=0,r=e.length;s!==r;++s){let o=e[s],c=n[o.id];c.needsUpdate!==!1&&o.setValue(t,c.value,a)}}static seqWithValue(t,e){let n=[];for(let a=0,s=t.length;a!==s;++a){let r=t[a];r.id in e&&n.push(r)}return n}};aM=37297,sM=0;Zp=new Dt;lM={[td]:"Linear",[ed]:"Reinhard",[nd]:"Cineon",[id]:"ACESFilmic",[sd]:"AgX",[rd]:"Neutral",[ad]:"Custom"};fl=new F;mM=/^[ \t]*#include +<([\w\d./]+)>/gm;bM=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;yM={[Pr]:"SHADOWMAP_TYPE_PCF",[ls]:"SHADOWMAP_TYPE_VSM"};vM={[ds]:"ENVMAP_MODE_REFRACTION"};SM={[Ic]:"ENVMAP_BLENDING_MULTIPLY",[Mp]:"ENVMAP_BLENDING_MIX",[Sp]:"ENVMAP_BLENDING_ADD"};EM=0,Fd=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(t,e,n){let a=this._getShaderCacheForMaterial(t);return a.has(e)===!1&&(a.add(e),e.usedTimes++),a.has(n)===!1&&(a.add(n),n.usedTimes++),this}remove(t){let e=this.materialCache.get(t);for(let n of e)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(t),this}getVertexShaderStage(t){return this._getShaderStage(t.vertexShader)}getFragmentShaderStage(t){return this._getShaderStage(t.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(t){let e=this.materialCache,n=e.get(t);return n===void 0&&(n=new Set,e.set(t,n)),n}_getShaderStage(t){let e=this.shaderCache,n=e.get(t);return n===void 0&&(n=new Bd(t),e.set(t,n)),n}},Bd=class{constructor(t){this.id=EM++,this.code=t,this.usedTimes=0}};DM=0;BM=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,kM=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,zM=[new F(1,0,0),new F(-1,0,0),new F(0,1,0),new F(0,-1,0),new F(0,0,1),new F(0,0,-1)],VM=[new F(0,-1,0),new F(0,-1,0),new F(0,0,1),new F(0,0,-1),new F(0,-1,0),new F(0,-1,0)],rm=new Zt,Wr=new F,Pd=new F;XM=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,qM=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,kd=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(t,e){if(this.texture===null){let n=new mr(t.texture);(t.depthNear!==e.depthNear||t.depthFar!==e.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=n}}getMesh(t){if(this.texture!==null&&this.mesh===null){let e=t.cameras[0].viewport,n=new Bn({vertexShader:XM,fragmentShader:qM,uniforms:{depthColor:{value:this.texture},depthWidth:{value:e.z},depthHeight:{value:e.w}}});this.mesh=new tn(new br(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},zd=class extends Yn{constructor(t,e){super();let n=this,a=null,s=1,r=null,o="local-floor",c=1,l=null,h=null,u=null,d=null,f=null,m=null,y=typeof XRWebGLBinding<"u",g=new kd,b={},v=e.getContextAttributes(),w=null,p=null,_=[],M=[],x=new Ct,S=null,E=null,A=new dn;A.viewport=new $t;let R=new dn;R.viewport=new $t;let C=[A,R],L=new Ac,N=null,U=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(X){let it=_[X];return it===void 0&&(it=new ns,_[X]=it),it.getTargetRaySpace()},this.getControllerGrip=function(X){let it=_[X];return it===void 0&&(it=new ns,_[X]=it),it.getGripSpace()},this.getHand=function(X){let it=_[X];return it===void 0&&(it=new ns,_[X]=it),it.getHandSpace()};function z(X){let it=M.indexOf(X.inputSource);if(it===-1)return;let _t=_[it];_t!==void 0&&(_t.update(X.inputSource,X.frame,l||r),_t.dispatchEvent({type:X.type,data:X.inputSource}))}function B(){a.removeEventListener("select",z),a.removeEventListener("selectstart",z),a.removeEventListener("selectend",z),a.removeEventListener("squeeze",z),a.removeEventListener("squeezestart",z),a.removeEventListener("squeezeend",z),a.removeEventListener("end",B),a.removeEventListener("inputsourceschange",K);for(let X=0;X<_.length;X++){let it=M[X];it!==null&&(M[X]=null,_[X].disconnect(it))}N=null,U=null,g.reset();for(let X in b)delete b[X];if(t.setRenderTarget(w),f=null,d=null,u=null,a=null,p=null,It.stop(),n.isPresenting=!1,t.setPixelRatio(S),t.setSize(x.width,x.height,!1),E!==null){let X=E.camera;X.fov=E.fov,X.zoom=E.zoom,X.updateProjectionMatrix(),E=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(X){s=X,n.isPresenting===!0&&Rt("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(X){o=X,n.isPresenting===!0&&Rt("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||r},this.setReferenceSpace=function(X){l=X},this.getBaseLayer=function(){return d!==null?d:f},this.getBinding=function(){return u===null&&y&&(u=new XRWebGLBinding(a,e)),u},this.getFrame=function(){return m},this.getSession=function(){return a},this.setSession=async function(X){if(a=X,a!==null){if(w=t.getRenderTarget(),a.addEventListener("select",z),a.addEventListener("selectstart",z),a.addEventListener("selectend",z),a.addEventListener("squeeze",z),a.addEventListener("squeezestart",z),a.addEventListener("squeezeend",z),a.addEventListener("end",B),a.addEventListener("inputsourceschange",K),v.xrCompatible!==!0&&await e.makeXRCompatible(),S=t.getPixelRatio(),t.getSize(x),y&&"createProjectionLayer"in XRWebGLBinding.prototype){let _t=null,Et=null,pt=null;v.depth&&(pt=v.stencil?e.DEPTH24_STENCIL8:e.DEPTH_COMPONENT24,_t=v.stencil?Li:Ii,Et=v.stencil?wa:Mn);let Ut={colorFormat:e.RGBA8,depthFormat:pt,scaleFactor:s};u=this.getBinding(),d=u.createProjectionLayer(Ut),a.updateRenderState({layers:[d]}),t.setPixelRatio(1),t.setSize(d.textureWidth,d.textureHeight,!1),p=new In(d.textureWidth,d.textureHeight,{format:mn,type:en,depthTexture:new Ni(d.textureWidth,d.textureHeight,Et,void 0,void 0,void 0,void 0,void 0,void 0,_t),stencilBuffer:v.stencil,colorSpace:t.outputColorSpace,samples:v.antialias?4:0,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}else{let _t={antialias:v.antialias,alpha:!0,depth:v.depth,stencil:v.stencil,framebufferScaleFactor:s};f=new XRWebGLLayer(a,e,_t),a.updateRenderState({baseLayer:f}),t.setPixelRatio(1),t.setSize(f.framebufferWidth,f.framebufferHeight,!1),p=new In(f.framebufferWidth,f.framebufferHeight,{format:mn,type:en,colorSpace:t.outputColorSpace,stencilBuffer:v.stencil,resolveDepthBuffer:f.ignoreDepthValues===!1,resolveStencilBuffer:f.ignoreDepthValues===!1,storeMultisampledDepthBuffer:f.ignoreDepthValues===!1,storeMultisampledStencilBuffer:f.ignoreDepthValues===!1})}p.isXRRenderTarget=!0,this.setFoveation(c),l=null,r=await a.requestReferenceSpace(o),It.setContext(a),It.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(a!==null)return a.environmentBlendMode},this.getDepthTexture=function(){return g.getDepthTexture()};function K(X){for(let it=0;it<X.removed.length;it++){let _t=X.removed[it],Et=M.indexOf(_t);Et>=0&&(M[Et]=null,_[Et].disconnect(_t))}for(let it=0;it<X.added.length;it++){let _t=X.added[it],Et=M.indexOf(_t);if(Et===-1){for(let Ut=0;Ut<_.length;Ut++)if(Ut>=M.length){M.push(_t),Et=Ut;break}else if(M[Ut]===null){M[Ut]=_t,Et=Ut;break}if(Et===-1)break}let pt=_[Et];pt&&pt.connect(_t)}}function W(X,it){it===null?X.matrixWorld.copy(X.matrix):X.matrixWorld.multiplyMatrices(it.matrixWorld,X.matrix),X.matrixWorldInverse.copy(X.matrixWorld).invert()}this.updateCamera=function(X){if(a===null)return;let it=X.near,_t=X.far;g.texture!==null&&(g.depthNear>0&&(it=g.depthNear),g.depthFar>0&&(_t=g.depthFar)),L.near=R.near=A.near=it,L.far=R.far=A.far=_t,(N!==L.near||U!==L.far)&&(a.updateRenderState({depthNear:L.near,depthFar:L.far}),N=L.near,U=L.far),L.layers.mask=X.layers.mask|6,A.layers.mask=L.layers.mask&-5,R.layers.mask=L.layers.mask&-3;let Et=X.parent,pt=L.cameras;W(L,Et);for(let Ut=0;Ut<pt.length;Ut++)W(pt[Ut],Et);L.projectionMatrix.copy(A.projectionMatrix),L.projectionMatrixInverse.copy(A.projectionMatrixInverse),E===null&&X.isPerspectiveCamera&&(E={camera:X,fov:X.fov,zoom:X.zoom}),Y(X,L,Et)};function Y(X,it,_t){_t===null?X.matrix.copy(it.matrixWorld):(X.matrix.copy(_t.matrixWorld),X.matrix.invert(),X.matrix.multiply(it.matrixWorld)),X.matrix.decompose(X.position,X.quaternion,X.scale),X.updateMatrixWorld(!0),X.projectionMatrix.copy(it.projectionMatrix),X.projectionMatrixInverse.copy(it.projectionMatrixInverse),X.isPerspectiveCamera&&(X.fov=Qa*2*Math.atan(1/X.projectionMatrix.elements[5]),X.zoom=1)}this.getCamera=function(){return L},this.getFoveation=function(){if(!(d===null&&f===null))return c},this.setFoveation=function(X){c=X,d!==null&&(d.fixedFoveation=X),f!==null&&f.fixedFoveation!==void 0&&(f.fixedFoveation=X)},this.hasDepthSensing=function(){return g.texture!==null},this.getDepthSensingMesh=function(){return g.getMesh(L)},this.getCameraTexture=function(X){return b[X]};let tt=null;function gt(X,it){if(h=it.getViewerPose(l||r),m=it,h!==null){let _t=h.views;f!==null&&(t.setRenderTargetFramebuffer(p,f.framebuffer),t.setRenderTarget(p));let Et=!1;_t.length!==L.cameras.length&&(L.cameras.length=0,Et=!0);for(let Nt=0;Nt<_t.length;Nt++){let Jt=_t[Nt],ce=null;if(f!==null)ce=f.getViewport(Jt);else{let Ve=u.getViewSubImage(d,Jt);ce=Ve.viewport,Nt===0&&(t.setRenderTargetTextures(p,Ve.colorTexture,Ve.depthStencilTexture),t.setRenderTarget(p))}let jt=C[Nt];jt===void 0&&(jt=new dn,jt.layers.enable(Nt),jt.viewport=new $t,C[Nt]=jt),jt.matrix.fromArray(Jt.transform.matrix),jt.matrix.decompose(jt.position,jt.quaternion,jt.scale),jt.projectionMatrix.fromArray(Jt.projectionMatrix),jt.projectionMatrixInverse.copy(jt.projectionMatrix).invert(),jt.viewport.set(ce.x,ce.y,ce.width,ce.height),Nt===0&&(L.matrix.copy(jt.matrix),L.matrix.decompose(L.position,L.quaternion,L.scale)),Et===!0&&L.cameras.push(jt)}let pt=a.enabledFeatures;if(pt&&pt.includes("depth-sensing")&&a.depthUsage=="gpu-optimized"&&y){u=n.getBinding();let Nt=u.getDepthInformation(_t[0]);Nt&&Nt.isValid&&Nt.texture&&g.init(Nt,a.renderState)}if(pt&&pt.includes("camera-access")&&y){t.state.unbindTexture(),u=n.getBinding();for(let Nt=0;Nt<_t.length;Nt++){let Jt=_t[Nt].camera;if(Jt){let ce=b[Jt];ce||(ce=new mr,b[Jt]=ce);let jt=u.getCameraImage(Jt);ce.sourceTexture=jt}}}}for(let _t=0;_t<_.length;_t++){let Et=M[_t],pt=_[_t];Et!==null&&pt!==void 0&&pt.update(Et,it,l||r)}tt&&tt(X,it),it.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:it}),m=null}let It=new om;It.setAnimationLoop(gt),this.setAnimationLoop=function(X){tt=X},this.dispose=function(){}}},YM=new Zt,bm=new Dt;bm.set(-1,0,0,0,1,0,0,0,1);ZM=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),di=null;ml=class{constructor(t={}){let{canvas:e=Lp(),context:n=null,depth:a=!0,stencil:s=!1,alpha:r=!1,antialias:o=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:d=!1,outputBufferType:f=en}=t;this.isWebGLRenderer=!0;let m;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");m=n.getContextAttributes().alpha}else m=r;let y=f,g=new Set([ps,fs,Aa]),b=new Set([en,Mn,Qi,wa,Pc,Lc]),v=new Uint32Array(4),w=new Int32Array(4),p={textures:[],min:[],max:[],resolution:[]},_=null,M=null,x=[],S=[],E=null;this.domElement=e,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=li,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let A=this,R=!1,C=null,L=null,N=null,U=null;this._outputColorSpace=En;let z=0,B=0,K=null,W=-1,Y=null,tt=new $t,gt=new $t,It=null,X=new kt(0),it=0,_t=e.width,Et=e.height,pt=1,Ut=null,ye=null,Nt=new $t(0,0,_t,Et),Jt=new $t(0,0,_t,Et),ce=!1,jt=new Ci,Ve=new lr,Ee=!1,yn=!1,ge=new Zt,ei=new F,De=new $t,Pn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},Ln=!1;function Dn(){return K===null?pt:1}let k=n;function Un(I,O){return e.getContext(I,O)}let pe,me,mt,Te,Pt,Ot,P,T,H,nt,Q,rt,dt,J,Z,ct,D,$,q,lt,st,ot,At;try{let I={alpha:!0,depth:a,stencil:s,antialias:o,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:h,failIfMajorPerformanceCaveat:u};if("setAttribute"in e&&e.setAttribute("data-engine",`three.js r${"187"}`),e.addEventListener("webglcontextlost",Tt,!1),e.addEventListener("webglcontextrestored",zt,!1),e.addEventListener("webglcontextcreationerror",bt,!1),k===null){let O="webgl2";if(k=Un(O,I),k===null)throw Un(O)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Vt()}catch(I){throw e.removeEventListener("webglcontextlost",Tt,!1),e.removeEventListener("webglcontextrestored",zt,!1),e.removeEventListener("webglcontextcreationerror",bt,!1),Lt("WebGLRenderer: "+I.message),I}function Vt(){pe=new lv(k),pe.init(),st=new jM(k,pe),me=new $_(k,pe,t,st),mt=new GM(k,pe),me.reversedDepthBuffer&&d&&mt.buffers.depth.setReversed(!0),L=k.createFramebuffer(),N=k.createFramebuffer(),U=k.createFramebuffer(),Te=new uv(k),Pt=new RM,Ot=new WM(k,pe,mt,Pt,me,st,Te),P=new cv(A),T=new p0(k),ot=new K_(k,T),H=new hv(k,T,Te,ot),nt=new pv(k,H,T,ot,Te),$=new fv(k,me,Ot),Z=new Q_(Pt),Q=new IM(A,P,pe,me,ot,Z),rt=new JM(A,Pt),dt=new NM,J=new FM(pe),D=new J_(A,P,mt,nt,m,c),ct=new HM(A,nt,me),At=new KM(k,Te,me,mt),q=new Z_(k,pe,Te),lt=new dv(k,pe,Te),Te.programs=Q.programs,A.capabilities=me,A.extensions=pe,A.properties=Pt,A.renderLists=dt,A.shadowMap=ct,A.state=mt,A.info=Te}y!==en&&(E=new gv(y,e.width,e.height,o,a,s));let at=new zd(A,k);this.xr=at,this.getContext=function(){return k},this.getContextAttributes=function(){return k.getContextAttributes()},this.forceContextLoss=function(){let I=pe.get("WEBGL_lose_context");I&&I.loseContext()},this.forceContextRestore=function(){let I=pe.get("WEBGL_lose_context");I&&I.restoreContext()},this.getPixelRatio=function(){return pt},this.setPixelRatio=function(I){I!==void 0&&(pt=I,this.setSize(_t,Et,!1))},this.getSize=function(I){return I.set(_t,Et)},this.setSize=function(I,O,j=!0){if(at.isPresenting){Rt("WebGLRenderer: Can't change size while VR device is presenting.");return}_t=I,Et=O,e.width=Math.floor(I*pt),e.height=Math.floor(O*pt),j===!0&&(e.style.width=I+"px",e.style.height=O+"px"),E!==null&&E.setSize(e.width,e.height),this.setViewport(0,0,I,O)},this.getDrawingBufferSize=function(I){return I.set(_t*pt,Et*pt).floor()},this.setDrawingBufferSize=function(I,O,j){_t=I,Et=O,pt=j,e.width=Math.floor(I*j),e.height=Math.floor(O*j),this.setViewport(0,0,I,O)},this.setEffects=function(I){if(y===en){Lt("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(I){for(let O=0;O<I.length;O++)if(I[O].isOutputPass===!0){Rt("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}E.setEffects(I||[])},this.getCurrentViewport=function(I){return I.copy(tt)},this.getViewport=function(I){return I.copy(Nt)},this.setViewport=function(I,O,j,V){I.isVector4?Nt.set(I.x,I.y,I.z,I.w):Nt.set(I,O,j,V),mt.viewport(tt.copy(Nt).multiplyScalar(Dn()).round())},this.getScissor=function(I){return I.copy(Jt)},this.setScissor=function(I,O,j,V){I.isVector4?Jt.set(I.x,I.y,I.z,I.w):Jt.set(I,O,j,V),mt.scissor(gt.copy(Jt).multiplyScalar(Dn()).round())},this.getScissorTest=function(){return ce},this.setScissorTest=function(I){mt.setScissorTest(ce=I)},this.setOpaqueSort=function(I){Ut=I},this.setTransparentSort=function(I){ye=I},this.getClearColor=function(I){return I.copy(D.getClearColor())},this.setClearColor=function(){D.setClearColor(...arguments)},this.getClearAlpha=function(){return D.getClearAlpha()},this.setClearAlpha=function(){D.setClearAlpha(...arguments)},this.clear=function(I=!0,O=!0,j=!0){let V=0;if(I){let G=!1;if(K!==null){let ut=K.texture.format;G=g.has(ut)}if(G){let ut=K.texture.type,vt=b.has(ut),ht=D.getClearColor(),yt=D.getClearAlpha(),wt=ht.r,Ft=ht.g,Xt=ht.b;vt?(v[0]=wt,v[1]=Ft,v[2]=Xt,v[3]=yt,k.clearBufferuiv(k.COLOR,0,v)):(w[0]=wt,w[1]=Ft,w[2]=Xt,w[3]=yt,k.clearBufferiv(k.COLOR,0,w))}else V|=k.COLOR_BUFFER_BIT}O&&(V|=k.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),j&&(V|=k.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),V!==0&&k.clear(V)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(I){I.setRenderer(this),C=I},this.dispose=function(){e.removeEventListener("webglcontextlost",Tt,!1),e.removeEventListener("webglcontextrestored",zt,!1),e.removeEventListener("webglcontextcreationerror",bt,!1),D.dispose(),dt.dispose(),J.dispose(),Ot.dispose(),Pt.dispose(),P.dispose(),nt.dispose(),H.dispose(),ot.dispose(),At.dispose(),Q.dispose(),at.dispose(),at.removeEventListener("sessionstart",Hu),at.removeEventListener("sessionend",Gu),la.stop()};function Tt(I){I.preventDefault(),ar("WebGLRenderer: Context Lost."),R=!0}function zt(){ar("WebGLRenderer: Context Restored."),R=!1;let I=Te.autoReset,O=ct.enabled,j=ct.autoUpdate,V=ct.needsUpdate,G=ct.type;Vt(),Te.autoReset=I,ct.enabled=O,ct.autoUpdate=j,ct.needsUpdate=V,ct.type=G}function bt(I){Lt("WebGLRenderer: A WebGL context could not be created. Reason: ",I.statusMessage)}function se(I){let O=I.target;O.removeEventListener("dispose",se),Ue(O)}function Ue(I){Bi(I),Pt.remove(I)}function Bi(I){let O=Pt.get(I).programs;O!==void 0&&(O.forEach(function(j){Q.releaseProgram(j)}),I.isShaderMaterial&&Q.releaseShaderCache(I))}this.renderBufferDirect=function(I,O,j,V,G,ut){O===null&&(O=Pn);let vt=G.isMesh&&G.matrixWorld.determinantAffine()<0,ht=Bb(I,O,j,V,G);mt.setMaterial(V,vt);let yt=j.index,wt=1;if(V.wireframe===!0){if(yt=H.getWireframeAttribute(j),yt===void 0)return;wt=2}let Ft=j.drawRange,Xt=j.attributes.position,Mt=Ft.start*wt,qt=(Ft.start+Ft.count)*wt;ut!==null&&(Mt=Math.max(Mt,ut.start*wt),qt=Math.min(qt,(ut.start+ut.count)*wt)),yt!==null?(Mt=Math.max(Mt,0),qt=Math.min(qt,yt.count)):Xt!=null&&(Mt=Math.max(Mt,0),qt=Math.min(qt,Xt.count));let Me=qt-Mt;if(Me<0||Me===1/0)return;ot.setup(G,V,ht,j,yt);let ue,le=q;if(yt!==null&&(ue=T.get(yt),le=lt,le.setIndex(ue)),G.isMesh)V.wireframe===!0?(mt.setLineWidth(V.wireframeLinewidth*Dn()),le.setMode(k.LINES)):le.setMode(k.TRIANGLES);else if(G.isLine){let Je=V.linewidth;Je===void 0&&(Je=1),mt.setLineWidth(Je*Dn()),G.isLineSegments?le.setMode(k.LINES):G.isLineLoop?le.setMode(k.LINE_LOOP):le.setMode(k.LINE_STRIP)}else G.isPoints?le.setMode(k.POINTS):G.isSprite&&le.setMode(k.TRIANGLES);if(G.isBatchedMesh)if(pe.get("WEBGL_multi_draw"))le.renderMultiDraw(G._multiDrawStarts,G._multiDrawCounts,G._multiDrawCount);else{let Je=G._multiDrawStarts,St=G._multiDrawCounts,cn=G._multiDrawCount,Qt=yt?T.get(yt).bytesPerElement:1,ha=Pt.get(V).currentProgram.getUniforms();for(let Ke=0;Ke<cn;Ke++)ha.setValue(k,"_gl_DrawID",Ke),le.render(Je[Ke]/Qt,St[Ke])}else if(G.isInstancedMesh)le.renderInstances(Mt,Me,G.count);else if(j.isInstancedBufferGeometry){let Je=j._maxInstanceCount!==void 0?j._maxInstanceCount:1/0,St=Math.min(j.instanceCount,Je);le.renderInstances(Mt,Me,St)}else le.render(Mt,Me)};function Vu(I,O,j,V){C!==null&&I.isNodeMaterial&&C.setObject(V,I),Ee===!0&&Z.setState(I,j,!1),I.transparent===!0&&I.side===kn&&I.forceSinglePass===!1?(I.side=Ge,I.needsUpdate=!0,Hs(I,O,V),I.side=ci,I.needsUpdate=!0,Hs(I,O,V),I.side=kn):Hs(I,O,V)}this.compile=function(I,O,j=null){j===null&&(j=I),C!==null&&C.renderStart(I,O,j),M=J.get(j),M.init(O),S.push(M),j.traverseVisible(function(G){G.isLight&&G.layers.test(O.layers)&&(M.pushLight(G),G.castShadow&&M.pushShadow(G))}),I!==j&&I.traverseVisible(function(G){G.isLight&&G.layers.test(O.layers)&&(M.pushLight(G),G.castShadow&&M.pushShadow(G))}),M.setupLights(),C!==null&&C.updateLights(M.state.lightsArray),yn=this.localClippingEnabled,Ee=Z.init(this.clippingPlanes,yn),Ee===!0&&Z.setGlobalState(this.clippingPlanes,O),C!==null&&ct.render(M.state.shadowsArray,j,O);let V=new Set;return I.traverse(function(G){if(!(G.isMesh||G.isPoints||G.isLine||G.isSprite))return;let ut=G.material;if(ut)if(Array.isArray(ut))for(let vt=0;vt<ut.length;vt++){let ht=ut[vt];Vu(ht,j,O,G),V.add(ht)}else Vu(ut,j,O,G),V.add(ut)}),M=S.pop(),C!==null&&C.renderEnd(),V},this.compileAsync=function(I,O,j=null){let V=this.compile(I,O,j);return new Promise(G=>{function ut(){if(V.forEach(function(vt){let yt=Pt.get(vt).currentProgram;(yt===void 0||yt.isReady())&&V.delete(vt)}),V.size===0){G(I);return}setTimeout(ut,10)}pe.get("KHR_parallel_shader_compile")!==null?ut():setTimeout(ut,10)})};let ah=null;function Ob(I){ah&&ah(I)}function Hu(){la.stop()}function Gu(){la.start()}let la=new om;la.setAnimationLoop(Ob),typeof self<"u"&&la.setContext(self),this.setAnimationLoop=function(I){ah=I,at.setAnimationLoop(I),I===null?la.stop():la.start()},at.addEventListener("sessionstart",Hu),at.addEventListener("sessionend",Gu),this.render=function(I,O){if(O!==void 0&&O.isCamera!==!0){Lt("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(R===!0)return;C!==null&&C.renderStart(I,O);let j=at.enabled===!0&&at.isPresenting===!0,V=E!==null&&(K===null||j)&&E.begin(A,K);if(I.matrixWorldAutoUpdate===!0&&I.updateMatrixWorld(),O.parent===null&&O.matrixWorldAutoUpdate===!0&&O.updateMatrixWorld(),at.enabled===!0&&at.isPresenting===!0&&(E===null||E.isCompositing()===!1)&&(at.cameraAutoUpdate===!0&&at.updateCamera(O),O=at.getCamera()),I.isScene===!0&&I.onBeforeRender(A,I,O,K),M=J.get(I,S.length),M.init(O),M.state.textureUnits=Ot.getTextureUnits(),S.push(M),ge.multiplyMatrices(O.projectionMatrix,O.matrixWorldInverse),O.isArrayCamera?Ve.setFromArrayCamera(O):jt.setFromProjectionMatrix(ge,Fn,O.reversedDepth),yn=this.localClippingEnabled,Ee=Z.init(this.clippingPlanes,yn),_=dt.get(I,x.length),_.init(),x.push(_),this.info.render.frame++,at.enabled===!0&&at.isPresenting===!0){let vt=A.xr.getDepthSensingMesh();vt!==null&&sh(vt,O,-1/0,A.sortObjects)}sh(I,O,0,A.sortObjects),_.finish(),C!==null&&C.updateLights(M.state.lightsArray),A.sortObjects===!0&&_.sort(Ut,ye),Ln=at.enabled===!1||at.isPresenting===!1||at.hasDepthSensing()===!1,Ln&&D.addToRenderList(_,I),this.info.autoReset===!0&&this.info.reset(),Ee===!0&&Z.beginShadows();let G=M.state.shadowsArray;if(ct.render(G,I,O),Ee===!0&&Z.endShadows(),(V&&E.hasRenderPass())===!1){let vt=_.opaque,ht=_.transmissive;if(M.setupLights(),O.isArrayCamera){let yt=O.cameras;if(ht.length>0)for(let wt=0,Ft=yt.length;wt<Ft;wt++){let Xt=yt[wt];ju(vt,ht,I,Xt)}Ln&&D.render(I);for(let wt=0,Ft=yt.length;wt<Ft;wt++){let Xt=yt[wt];Wu(_,I,Xt,Xt.viewport)}}else ht.length>0&&ju(vt,ht,I,O),Ln&&D.render(I),Wu(_,I,O)}K!==null&&B===0&&(Ot.updateMultisampleRenderTarget(K),Ot.updateRenderTargetMipmap(K)),V&&E.end(A),I.isScene===!0&&I.onAfterRender(A,I,O),ot.resetDefaultState(),W=-1,Y=null,S.pop(),S.length>0?(M=S[S.length-1],Ot.setTextureUnits(M.state.textureUnits),Ee===!0&&Z.setGlobalState(A.clippingPlanes,M.state.camera)):M=null,x.pop(),x.length>0?_=x[x.length-1]:_=null,C!==null&&C.renderEnd()};function sh(I,O,j,V){if(I.visible===!1)return;if(I.layers.test(O.layers)){if(I.isGroup)j=I.renderOrder;else if(I.isLOD)I.autoUpdate===!0&&I.update(O);else if(I.isLight)M.pushLight(I),I.castShadow&&M.pushShadow(I);else if(I.isSprite){let vt=O.isArrayCamera?Ve:jt;if(!I.frustumCulled||I.intersectsFrustum(vt)){V&&De.setFromMatrixPosition(I.matrixWorld).applyMatrix4(ge);let ht=nt.update(I),yt=I.material;yt.visible&&_.push(I,ht,yt,j,De.z,null,O)}}else if(I.isMesh||I.isLine||I.isPoints){let vt=O.isArrayCamera?Ve:jt;if(!I.frustumCulled||I.intersectsFrustum(vt)){let ht=nt.update(I),yt=I.material;if(V&&(I.boundingSphere!==void 0?(I.boundingSphere===null&&I.computeBoundingSphere(),De.copy(I.boundingSphere.center)):(ht.boundingSphere===null&&ht.computeBoundingSphere(),De.copy(ht.boundingSphere.center)),De.applyMatrix4(I.matrixWorld).applyMatrix4(ge)),Array.isArray(yt)){let wt=ht.groups;for(let Ft=0,Xt=wt.length;Ft<Xt;Ft++){let Mt=wt[Ft],qt=yt[Mt.materialIndex];qt&&qt.visible&&_.push(I,ht,qt,j,De.z,Mt,O)}}else yt.visible&&_.push(I,ht,yt,j,De.z,null,O)}}}let ut=I.children;for(let vt=0,ht=ut.length;vt<ht;vt++)sh(ut[vt],O,j,V)}function Wu(I,O,j,V){let{opaque:G,transmissive:ut,transparent:vt}=I;M.setupLightsView(j),Ee===!0&&Z.setGlobalState(A.clippingPlanes,j),V&&mt.viewport(tt.copy(V)),G.length>0&&uo(G,O,j),ut.length>0&&uo(ut,O,j),vt.length>0&&uo(vt,O,j),mt.buffers.depth.setTest(!0),mt.buffers.depth.setMask(!0),mt.buffers.color.setMask(!0),mt.setPolygonOffset(!1)}function ju(I,O,j,V){if((j.isScene===!0?j.overrideMaterial:null)!==null)return;if(M.state.transmissionRenderTarget[V.id]===void 0){let Mt=pe.has("EXT_color_buffer_half_float")||pe.has("EXT_color_buffer_float");M.state.transmissionRenderTarget[V.id]=new In(1,1,{generateMipmaps:!0,type:Mt?Zn:en,minFilter:Pi,samples:Math.max(4,me.samples),stencilBuffer:s,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:Gt.workingColorSpace})}let ut=M.state.transmissionRenderTarget[V.id],vt=V.viewport||tt;ut.setSize(vt.z*A.transmissionResolutionScale,vt.w*A.transmissionResolutionScale);let ht=A.getRenderTarget(),yt=A.getActiveCubeFace(),wt=A.getActiveMipmapLevel();A.setRenderTarget(ut),A.getClearColor(X),it=A.getClearAlpha(),it<1&&A.setClearColor(16777215,.5),A.clear(),Ln&&D.render(j);let Ft=A.toneMapping;A.toneMapping=li;let Xt=V.viewport;if(V.viewport!==void 0&&(V.viewport=void 0),M.setupLightsView(V),Ee===!0&&Z.setGlobalState(A.clippingPlanes,V),uo(I,j,V),Ot.updateMultisampleRenderTarget(ut),Ot.updateRenderTargetMipmap(ut),pe.has("WEBGL_multisampled_render_to_texture")===!1){let Mt=!1;for(let qt=0,Me=O.length;qt<Me;qt++){let ue=O[qt],{object:le,geometry:Je,material:St,group:cn}=ue;if(St.side===kn&&le.layers.test(V.layers)){let Qt=St.side;St.side=Ge,St.needsUpdate=!0,Xu(le,j,V,Je,St,cn),St.side=Qt,St.needsUpdate=!0,Mt=!0}}Mt===!0&&(Ot.updateMultisampleRenderTarget(ut),Ot.updateRenderTargetMipmap(ut))}A.setRenderTarget(ht,yt,wt),A.setClearColor(X,it),Xt!==void 0&&(V.viewport=Xt),A.toneMapping=Ft}function uo(I,O,j){let V=O.isScene===!0?O.overrideMaterial:null;for(let G=0,ut=I.length;G<ut;G++){let vt=I[G],{object:ht,geometry:yt,group:wt}=vt,Ft=vt.material;Ft.allowOverride===!0&&V!==null&&(Ft=V),ht.layers.test(j.layers)&&Xu(ht,O,j,yt,Ft,wt)}}function Xu(I,O,j,V,G,ut){C!==null&&G.isNodeMaterial&&C.setObject(I,G),I.onBeforeRender(A,O,j,V,G,ut),I.modelViewMatrix.multiplyMatrices(j.matrixWorldInverse,I.matrixWorld),I.normalMatrix.getNormalMatrix(I.modelViewMatrix),G.onBeforeRender(A,O,j,V,I,ut),G.transparent===!0&&G.side===kn&&G.forceSinglePass===!1?(G.side=Ge,G.needsUpdate=!0,A.renderBufferDirect(j,O,V,G,I,ut),G.side=ci,G.needsUpdate=!0,A.renderBufferDirect(j,O,V,G,I,ut),G.side=kn):A.renderBufferDirect(j,O,V,G,I,ut),I.onAfterRender(A,O,j,V,G,ut)}function qu(I){let O=0;for(let j of I)j.texture!==null&&O++;return O}function Hs(I,O,j){O.isScene!==!0&&(O=Pn);let V=Pt.get(I),G=M.state.lights,ut=M.state.shadowsArray,vt=G.state.version,ht=Q.getParameters(I,G.state,ut,O,j,M.state.lightProbeGridArray),yt=Q.getProgramCacheKey(ht),wt=V.programs;V.environment=I.isMeshStandardMaterial||I.isMeshLambertMaterial||I.isMeshPhongMaterial?O.environment:null,V.fog=O.fog;let Ft=I.isMeshStandardMaterial||I.isMeshLambertMaterial&&!I.envMap||I.isMeshPhongMaterial&&!I.envMap;V.envMap=P.get(I.envMap||V.environment,Ft),V.envMapRotation=V.environment!==null&&I.envMap===null?O.environmentRotation:I.envMapRotation,wt===void 0&&(I.addEventListener("dispose",se),wt=new Map,V.programs=wt,V.programVariants=new Map);let Xt=wt.get(yt);if(Xt!==void 0){if(V.currentProgram===Xt&&V.lightsStateVersion===vt)return Ju(I,ht),Xt}else ht.uniforms=Q.getUniforms(I),C!==null&&I.isNodeMaterial&&C.build(I,j,ht),I.onBeforeCompile(ht,A),Xt=Q.acquireProgram(ht,yt),wt.set(yt,Xt),V.uniforms=ht.uniforms;let Mt=V.uniforms;return(!I.isShaderMaterial&&!I.isRawShaderMaterial||I.clipping===!0)&&(Mt.clippingPlanes=Z.uniform),Ju(I,ht),V.needsLights=zb(I),V.lightsStateVersion=vt,V.needsLights&&(Mt.ambientLightColor.value=G.state.ambient,Mt.lightProbe.value=G.state.probe,Mt.sunLights.value=G.state.sun,Mt.sunLightShadows.value=G.state.sunShadow,Mt.directionalLights.value=G.state.directional,Mt.directionalLightShadows.value=G.state.directionalShadow,Mt.spotLights.value=G.state.spot,Mt.spotLightShadows.value=G.state.spotShadow,Mt.rectAreaLights.value=G.state.rectArea,Mt.ltc_1.value=G.state.rectAreaLTC1,Mt.ltc_2.value=G.state.rectAreaLTC2,Mt.pointLights.value=G.state.point,Mt.pointLightShadows.value=G.state.pointShadow,Mt.hemisphereLights.value=G.state.hemi,Mt.sunShadowMatrix.value=G.state.sunShadowMatrix,Mt.sunShadowCascade.value=G.state.sunShadowCascade,Mt.directionalShadowMatrix.value=G.state.directionalShadowMatrix,Mt.spotLightMatrix.value=G.state.spotLightMatrix,Mt.spotLightMap.value=G.state.spotLightMap,Mt.pointShadowMatrix.value=G.state.pointShadowMatrix),V.numLightProbeGrids=qu(M.state.lightProbeGridArray),V.currentProgram=Xt,V.uniformsList=null,Xt}function Fb(I,O,j,V,G){let ut=Pt.get(I),vt=ut.currentProgram.id+","+V+","+G,ht=ut.programVariants.get(vt);return ht===void 0?(ht=Hs(I,O,j),ut.programVariants.set(vt,ht)):(ut.currentProgram=ht,ut.uniformsList=null,ut.outputColorSpace=V,ut.toneMapping=G),ht}function Yu(I){if(I.uniformsList===null){let O=I.currentProgram.getUniforms();I.uniformsList=ms.seqWithValue(O.seq,I.uniforms)}return I.uniformsList}function Ju(I,O){let j=Pt.get(I);j.outputColorSpace=O.outputColorSpace,j.batching=O.batching,j.batchingColor=O.batchingColor,j.instancing=O.instancing,j.instancingColor=O.instancingColor,j.instancingMorph=O.instancingMorph,j.skinning=O.skinning,j.morphTargets=O.morphTargets,j.morphNormals=O.morphNormals,j.morphColors=O.morphColors,j.morphTargetsCount=O.morphTargetsCount,j.numClippingPlanes=O.numClippingPlanes,j.numIntersection=O.numClipIntersection,j.vertexAlphas=O.vertexAlphas,j.vertexTangents=O.vertexTangents,j.toneMapping=O.toneMapping}function Bb(I,O,j,V,G){O.isScene!==!0&&(O=Pn),Ot.resetTextureUnits();let ut=O.fog,vt=V.isMeshStandardMaterial||V.isMeshLambertMaterial||V.isMeshPhongMaterial?O.environment:null,ht=K===null?A.outputColorSpace:K.isXRRenderTarget===!0?K.texture.colorSpace:Gt.workingColorSpace,yt=V.isMeshStandardMaterial||V.isMeshLambertMaterial&&!V.envMap||V.isMeshPhongMaterial&&!V.envMap,wt=P.get(V.envMap||vt,yt),Ft=V.vertexColors===!0&&!!j.attributes.color&&j.attributes.color.itemSize===4,Xt=!!j.attributes.tangent&&(!!V.normalMap||V.anisotropy>0),Mt=!!j.morphAttributes.position,qt=!!j.morphAttributes.normal,Me=!!j.morphAttributes.color,ue=li;V.toneMapped&&(K===null||K.isXRRenderTarget===!0)&&(ue=A.toneMapping);let le=j.morphAttributes.position||j.morphAttributes.normal||j.morphAttributes.color,Je=le!==void 0?le.length:0,St=Pt.get(V),cn=M.state.lights;if(Ee===!0&&(yn===!0||I!==Y)){let be=I===Y&&V.id===W;Z.setState(V,I,be)}let Qt=!1,ha=!1;V.version===St.__version?St.needsLights&&St.lightsStateVersion!==cn.state.version||G.isBatchedMesh&&St.batching===!1||!G.isBatchedMesh&&St.batching===!0||G.isBatchedMesh&&St.batchingColor===!0&&G._colorsTexture===null||G.isBatchedMesh&&St.batchingColor===!1&&G._colorsTexture!==null||G.isInstancedMesh&&St.instancing===!1||!G.isInstancedMesh&&St.instancing===!0||G.isSkinnedMesh&&St.skinning===!1||!G.isSkinnedMesh&&St.skinning===!0||G.isInstancedMesh&&St.instancingColor===!0&&G.instanceColor===null||G.isInstancedMesh&&St.instancingColor===!1&&G.instanceColor!==null||G.isInstancedMesh&&St.instancingMorph===!0&&G.morphTexture===null||G.isInstancedMesh&&St.instancingMorph===!1&&G.morphTexture!==null||St.envMap!==wt||V.fog===!0&&St.fog!==ut||St.numClippingPlanes!==void 0&&(St.numClippingPlanes!==Z.numPlanes||St.numIntersection!==Z.numIntersection)||St.vertexAlphas!==Ft||St.vertexTangents!==Xt||St.morphTargets!==Mt||St.morphNormals!==qt||St.morphColors!==Me||St.morphTargetsCount!==Je||St.numLightProbeGrids!==qu(M.state.lightProbeGridArray)?Qt=!0:(St.outputColorSpace!==ht||St.toneMapping!==ue)&&(ha=!0):(Qt=!0,St.__version=V.version);let Ke=St.currentProgram;(Qt===!0||ha===!0)&&(Ke=ha===!0?Fb(V,O,G,ht,ue):Hs(V,O,G),C&&V.isNodeMaterial&&C.onUpdateProgram(V,Ke,St));let fo=!1,ki=!1,da=!1,Kt=Ke.getUniforms(),He=St.uniforms;if(mt.useProgram(Ke.program)&&(fo=!0,ki=!0,da=!0),V.id!==W&&(W=V.id,ki=!0),fo||Y!==I){mt.buffers.depth.getReversed()&&I.reversedDepth!==!0&&(I._reversedDepth=!0,I.updateProjectionMatrix()),Kt.setValue(k,"projectionMatrix",I.projectionMatrix),Kt.setValue(k,"viewMatrix",I.matrixWorldInverse);let Oe=Kt.map.cameraPosition;Oe!==void 0&&Oe.setValue(k,ei.setFromMatrixPosition(I.matrixWorld)),me.logarithmicDepthBuffer&&Kt.setValue(k,"logDepthBufFC",2/(Math.log(I.far+1)/Math.LN2)),(V.isMeshPhongMaterial||V.isMeshToonMaterial||V.isMeshLambertMaterial||V.isMeshBasicMaterial||V.isMeshStandardMaterial||V.isShaderMaterial)&&Kt.setValue(k,"isOrthographic",I.isOrthographicCamera===!0),Y!==I&&(Y=I,ki=!0,da=!0)}if(St.needsLights&&(cn.state.sunShadowMap.length>0&&Kt.setValue(k,"sunShadowMap",cn.state.sunShadowMap,Ot),cn.state.directionalShadowMap.length>0&&Kt.setValue(k,"directionalShadowMap",cn.state.directionalShadowMap,Ot),cn.state.spotShadowMap.length>0&&Kt.setValue(k,"spotShadowMap",cn.state.spotShadowMap,Ot),cn.state.pointShadowMap.length>0&&Kt.setValue(k,"pointShadowMap",cn.state.pointShadowMap,Ot)),G.isSkinnedMesh){Kt.setOptional(k,G,"bindMatrix"),Kt.setOptional(k,G,"bindMatrixInverse");let be=G.skeleton;be&&(be.boneTexture===null&&be.computeBoneTexture(),Kt.setValue(k,"boneTexture",be.boneTexture,Ot))}G.isBatchedMesh&&(Kt.setOptional(k,G,"batchingTexture"),Kt.setValue(k,"batchingTexture",G._matricesTexture,Ot),Kt.setOptional(k,G,"batchingIdTexture"),Kt.setValue(k,"batchingIdTexture",G._indirectTexture,Ot),Kt.setOptional(k,G,"batchingColorTexture"),G._colorsTexture!==null&&Kt.setValue(k,"batchingColorTexture",G._colorsTexture,Ot));let Gn=j.morphAttributes;if((Gn.position!==void 0||Gn.normal!==void 0||Gn.color!==void 0)&&$.update(G,j,Ke),(ki||St.receiveShadow!==G.receiveShadow)&&(St.receiveShadow=G.receiveShadow,Kt.setValue(k,"receiveShadow",G.receiveShadow)),(V.isMeshStandardMaterial||V.isMeshLambertMaterial||V.isMeshPhongMaterial)&&V.envMap===null&&O.environment!==null&&(He.envMapIntensity.value=O.environmentIntensity),He.dfgLUT!==void 0&&(He.dfgLUT.value=$M()),ki){if(Kt.setValue(k,"toneMappingExposure",A.toneMappingExposure),St.needsLights&&kb(He,da),ut&&V.fog===!0&&rt.refreshFogUniforms(He,ut),rt.refreshMaterialUniforms(He,V,pt,Et,M.state.transmissionRenderTarget[I.id]),St.needsLights&&St.numLightProbeGrids>0){let be=p,Oe=0;for(let yi of M.state.lightProbeGridArray)yi.texture!==null&&(be.textures[Oe]=yi.texture,be.min[Oe]=yi.boundingBox.min,be.max[Oe]=yi.boundingBox.max,be.resolution[Oe]=yi.resolution,Oe++);for(let yi in be)be[yi].length=Oe;He.probesSH.value=be.textures,He.probesMin.value=be.min,He.probesMax.value=be.max,He.probesResolution.value=be.resolution}ms.upload(k,Yu(St),He,Ot)}if(V.isShaderMaterial&&V.uniformsNeedUpdate===!0&&(ms.upload(k,Yu(St),He,Ot),V.uniformsNeedUpdate=!1),V.isSpriteMaterial&&Kt.setValue(k,"center",G.center),Kt.setValue(k,"modelViewMatrix",G.modelViewMatrix),Kt.setValue(k,"normalMatrix",G.normalMatrix),Kt.setValue(k,"modelMatrix",G.matrixWorld),V.uniformsGroups!==void 0){let be=V.uniformsGroups;for(let Oe=0,yi=be.length;Oe<yi;Oe++){let Zu=be[Oe];At.update(Zu,Ke),At.bind(Zu,Ke)}}return Ke}function kb(I,O){I.ambientLightColor.needsUpdate=O,I.lightProbe.needsUpdate=O,I.sunLights.needsUpdate=O,I.sunLightShadows.needsUpdate=O,I.directionalLights.needsUpdate=O,I.directionalLightShadows.needsUpdate=O,I.pointLights.needsUpdate=O,I.pointLightShadows.needsUpdate=O,I.spotLights.needsUpdate=O,I.spotLightShadows.needsUpdate=O,I.rectAreaLights.needsUpdate=O,I.hemisphereLights.needsUpdate=O}function zb(I){return I.isMeshLambertMaterial||I.isMeshToonMaterial||I.isMeshPhongMaterial||I.isMeshStandardMaterial||I.isShadowMaterial||I.isShaderMaterial&&I.lights===!0}this.getActiveCubeFace=function(){return z},this.getActiveMipmapLevel=function(){return B},this.getRenderTarget=function(){return K},this.setRenderTargetTextures=function(I,O,j){let V=Pt.get(I);V.__autoAllocateDepthBuffer=I.resolveDepthBuffer===!1,V.__autoAllocateDepthBuffer===!1&&(V.__useRenderToTexture=!1),Pt.get(I.texture).__webglTexture=O,Pt.get(I.depthTexture).__webglTexture=V.__autoAllocateDepthBuffer?void 0:j,V.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(I,O){let j=Pt.get(I);j.__webglFramebuffer=O,j.__useDefaultFramebuffer=O===void 0},this.setRenderTarget=function(I,O=0,j=0){K=I,z=O,B=j;let V=null,G=!1,ut=!1;if(I){let ht=Pt.get(I);if(ht.__useDefaultFramebuffer!==void 0){mt.bindFramebuffer(k.FRAMEBUFFER,ht.__webglFramebuffer),tt.copy(I.viewport),gt.copy(I.scissor),It=I.scissorTest,mt.viewport(tt),mt.scissor(gt),mt.setScissorTest(It),W=-1;return}else if(ht.__webglFramebuffer===void 0)Ot.setupRenderTarget(I);else if(ht.__hasExternalTextures)Ot.rebindTextures(I,Pt.get(I.texture).__webglTexture,Pt.get(I.depthTexture).__webglTexture);else if(I.depthBuffer){let Ft=I.depthTexture;if(ht.__boundDepthTexture!==Ft){if(Ft!==null&&Pt.has(Ft)&&(I.width!==Ft.image.width||I.height!==Ft.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Ot.setupDepthRenderbuffer(I)}}let yt=I.texture;(yt.isData3DTexture||yt.isDataArrayTexture||yt.isCompressedArrayTexture)&&(ut=!0);let wt=Pt.get(I).__webglFramebuffer;I.isWebGLCubeRenderTarget?(Array.isArray(wt[O])?V=wt[O][j]:V=wt[O],G=!0):I.samples>0&&Ot.useMultisampledRTT(I)===!1?V=Pt.get(I).__webglMultisampledFramebuffer:Array.isArray(wt)?V=wt[j]:V=wt,tt.copy(I.viewport),gt.copy(I.scissor),It=I.scissorTest}else tt.copy(Nt).multiplyScalar(pt).floor(),gt.copy(Jt).multiplyScalar(pt).floor(),It=ce;if(j!==0&&(V=L),mt.bindFramebuffer(k.FRAMEBUFFER,V)&&mt.drawBuffers(I,V),mt.viewport(tt),mt.scissor(gt),mt.setScissorTest(It),G){let ht=Pt.get(I.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_CUBE_MAP_POSITIVE_X+O,ht.__webglTexture,j)}else if(ut){let ht=O;for(let yt=0;yt<I.textures.length;yt++){let wt=Pt.get(I.textures[yt]);k.framebufferTextureLayer(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0+yt,wt.__webglTexture,j,ht)}}else if(I!==null&&j!==0){let ht=Pt.get(I.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,ht.__webglTexture,j)}W=-1};function Ku(I){let O=Pt.get(I);return(O.__readFormat!==I.format||O.__readType!==I.type)&&(O.__readFormat=I.format,O.__readType=I.type,O.__formatReadable=me.textureFormatReadable(I.format),O.__typeReadable=me.textureTypeReadable(I.type)),O}this.readRenderTargetPixels=function(I,O,j,V,G,ut,vt,ht=0){if(!(I&&I.isWebGLRenderTarget)){Lt("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let yt=Pt.get(I).__webglFramebuffer;if(I.isWebGLCubeRenderTarget&&vt!==void 0&&(yt=yt[vt],Array.isArray(yt)&&(yt=yt[0])),yt){mt.bindFramebuffer(k.FRAMEBUFFER,yt);try{let wt=I.textures[ht],Ft=wt.format,Xt=wt.type;I.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+ht);let Mt=Ku(wt);if(Mt.__formatReadable===!1){Lt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(Mt.__typeReadable===!1){Lt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}O>=0&&O<=I.width-V&&j>=0&&j<=I.height-G&&k.readPixels(O,j,V,G,st.convert(Ft),st.convert(Xt),ut)}finally{let wt=K!==null?Pt.get(K).__webglFramebuffer:null;mt.bindFramebuffer(k.FRAMEBUFFER,wt)}}},this.readRenderTargetPixelsAsync=async function(I,O,j,V,G,ut,vt,ht=0){if(!(I&&I.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let yt=Pt.get(I).__webglFramebuffer;if(I.isWebGLCubeRenderTarget&&vt!==void 0&&(yt=yt[vt],Array.isArray(yt)&&(yt=yt[0])),yt)if(O>=0&&O<=I.width-V&&j>=0&&j<=I.height-G){mt.bindFramebuffer(k.FRAMEBUFFER,yt);let wt=I.textures[ht],Ft=wt.format,Xt=wt.type;I.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+ht);let Mt=Ku(wt);if(Mt.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(Mt.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let qt=k.createBuffer();k.bindBuffer(k.PIXEL_PACK_BUFFER,qt),k.bufferData(k.PIXEL_PACK_BUFFER,ut.byteLength,k.STREAM_READ),k.readPixels(O,j,V,G,st.convert(Ft),st.convert(Xt),0),k.bindBuffer(k.PIXEL_PACK_BUFFER,null);let Me=K!==null?Pt.get(K).__webglFramebuffer:null;mt.bindFramebuffer(k.FRAMEBUFFER,Me);let ue=k.fenceSync(k.SYNC_GPU_COMMANDS_COMPLETE,0);return k.flush(),await Up(k,ue,4),k.bindBuffer(k.PIXEL_PACK_BUFFER,qt),k.getBufferSubData(k.PIXEL_PACK_BUFFER,0,ut),k.bindBuffer(k.PIXEL_PACK_BUFFER,null),k.deleteBuffer(qt),k.deleteSync(ue),ut}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(I,O=null,j=0){let V=Math.pow(2,-j),G=Math.floor(I.image.width*V),ut=Math.floor(I.image.height*V),vt=O!==null?O.x:0,ht=O!==null?O.y:0;Ot.setTexture2D(I,0),k.copyTexSubImage2D(k.TEXTURE_2D,j,0,0,vt,ht,G,ut),mt.unbindTexture()},this.copyTextureToTexture=function(I,O,j=null,V=null,G=0,ut=0){let vt,ht,yt,wt,Ft,Xt,Mt,qt,Me,ue=I.isCompressedTexture?I.mipmaps[ut]:I.image;if(j!==null)vt=j.max.x-j.min.x,ht=j.max.y-j.min.y,yt=j.isBox3?j.max.z-j.min.z:1,wt=j.min.x,Ft=j.min.y,Xt=j.isBox3?j.min.z:0;else{let Kt=Math.pow(2,-G);vt=Math.floor(ue.width*Kt),ht=Math.floor(ue.height*Kt),I.isDataArrayTexture?yt=ue.depth:I.isData3DTexture?yt=Math.floor(ue.depth*Kt):yt=1,wt=0,Ft=0,Xt=0}V!==null?(Mt=V.x,qt=V.y,Me=V.z):(Mt=0,qt=0,Me=0);let le=st.convert(O.format),Je=st.convert(O.type),St;O.isData3DTexture?(Ot.setTexture3D(O,0),St=k.TEXTURE_3D):O.isDataArrayTexture||O.isCompressedArrayTexture?(Ot.setTexture2DArray(O,0),St=k.TEXTURE_2D_ARRAY):(Ot.setTexture2D(O,0),St=k.TEXTURE_2D),mt.activeTexture(k.TEXTURE0),mt.pixelStorei(k.UNPACK_FLIP_Y_WEBGL,O.flipY),mt.pixelStorei(k.UNPACK_PREMULTIPLY_ALPHA_WEBGL,O.premultiplyAlpha),mt.pixelStorei(k.UNPACK_ALIGNMENT,O.unpackAlignment);let cn=mt.getParameter(k.UNPACK_ROW_LENGTH),Qt=mt.getParameter(k.UNPACK_IMAGE_HEIGHT),ha=mt.getParameter(k.UNPACK_SKIP_PIXELS),Ke=mt.getParameter(k.UNPACK_SKIP_ROWS),fo=mt.getParameter(k.UNPACK_SKIP_IMAGES);mt.pixelStorei(k.UNPACK_ROW_LENGTH,ue.width),mt.pixelStorei(k.UNPACK_IMAGE_HEIGHT,ue.height),mt.pixelStorei(k.UNPACK_SKIP_PIXELS,wt),mt.pixelStorei(k.UNPACK_SKIP_ROWS,Ft),mt.pixelStorei(k.UNPACK_SKIP_IMAGES,Xt);let ki=I.isDataArrayTexture||I.isData3DTexture,da=O.isDataArrayTexture||O.isData3DTexture;if(I.isDepthTexture){let Kt=Pt.get(I),He=Pt.get(O),Gn=Pt.get(Kt.__renderTarget),be=Pt.get(He.__renderTarget);mt.bindFramebuffer(k.READ_FRAMEBUFFER,Gn.__webglFramebuffer),mt.bindFramebuffer(k.DRAW_FRAMEBUFFER,be.__webglFramebuffer);for(let Oe=0;Oe<yt;Oe++)ki&&(k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,Pt.get(I).__webglTexture,G,Xt+Oe),k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,Pt.get(O).__webglTexture,ut,Me+Oe)),k.blitFramebuffer(wt,Ft,wt+vt,Ft+ht,Mt,qt,Mt+vt,qt+ht,k.DEPTH_BUFFER_BIT,k.NEAREST);mt.bindFramebuffer(k.READ_FRAMEBUFFER,null),mt.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else if(G!==0||I.isRenderTargetTexture||Pt.has(I)){let Kt=Pt.get(I),He=Pt.get(O);mt.bindFramebuffer(k.READ_FRAMEBUFFER,N),mt.bindFramebuffer(k.DRAW_FRAMEBUFFER,U);for(let Gn=0;Gn<yt;Gn++)ki?k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,Kt.__webglTexture,G,Xt+Gn):k.framebufferTexture2D(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,Kt.__webglTexture,G),da?k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,He.__webglTexture,ut,Me+Gn):k.framebufferTexture2D(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,He.__webglTexture,ut),G!==0?k.blitFramebuffer(wt,Ft,wt+vt,Ft+ht,Mt,qt,Mt+vt,qt+ht,k.COLOR_BUFFER_BIT,k.NEAREST):da?k.copyTexSubImage3D(St,ut,Mt,qt,Me+Gn,wt,Ft,vt,ht):k.copyTexSubImage2D(St,ut,Mt,qt,wt,Ft,vt,ht);mt.bindFramebuffer(k.READ_FRAMEBUFFER,null),mt.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else da?I.isDataTexture||I.isData3DTexture?k.texSubImage3D(St,ut,Mt,qt,Me,vt,ht,yt,le,Je,ue.data):O.isCompressedArrayTexture?k.compressedTexSubImage3D(St,ut,Mt,qt,Me,vt,ht,yt,le,ue.data):k.texSubImage3D(St,ut,Mt,qt,Me,vt,ht,yt,le,Je,ue):I.isDataTexture?k.texSubImage2D(k.TEXTURE_2D,ut,Mt,qt,vt,ht,le,Je,ue.data):I.isCompressedTexture?k.compressedTexSubImage2D(k.TEXTURE_2D,ut,Mt,qt,ue.width,ue.height,le,ue.data):k.texSubImage2D(k.TEXTURE_2D,ut,Mt,qt,vt,ht,le,Je,ue);mt.pixelStorei(k.UNPACK_ROW_LENGTH,cn),mt.pixelStorei(k.UNPACK_IMAGE_HEIGHT,Qt),mt.pixelStorei(k.UNPACK_SKIP_PIXELS,ha),mt.pixelStorei(k.UNPACK_SKIP_ROWS,Ke),mt.pixelStorei(k.UNPACK_SKIP_IMAGES,fo),ut===0&&O.generateMipmaps===!0&&O.mipmapsAutoUpdate===!0&&k.generateMipmap(St),mt.unbindTexture()},this.initRenderTarget=function(I){Pt.get(I).__webglFramebuffer===void 0&&Ot.setupRenderTarget(I)},this.initTexture=function(I){I.isCubeTexture?Ot.setTextureCube(I,0):I.isData3DTexture?Ot.setTexture3D(I,0):I.isDataArrayTexture||I.isCompressedArrayTexture?Ot.setTexture2DArray(I,0):Ot.setTexture2D(I,0),mt.unbindTexture()},this.resetState=function(){z=0,B=0,K=null,mt.reset(),ot.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Fn}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(t){this._outputColorSpace=t;let e=this.getContext();e.drawingBufferColorSpace=Gt._getDrawingBufferColorSpace(t),e.unpackColorSpace=Gt._getUnpackColorSpace()}}});function tS(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function eS(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function nS(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(_m),this.state=te.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let t=this._pointers[0],e=this._pointerPositions[t];this._onTouchStart({pointerId:t,pageX:e.x,pageY:e.y});break}}function iS(i){let t;switch(i.button){case 0:t=this.mouseButtons.LEFT;break;case 1:t=this.mouseButtons.MIDDLE;break;case 2:t=this.mouseButtons.RIGHT;break;default:t=-1}switch(t){case $i.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=te.DOLLY;break;case $i.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=te.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=te.ROTATE}break;case $i.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=te.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=te.PAN}break;default:this.state=te.NONE}this.state!==te.NONE&&this.dispatchEvent(Hd)}function aS(i){switch(this.state){case te.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case te.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case te.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function sS(i){this.enabled===!1||this.enableZoom===!1||this.state!==te.NONE||(i.preventDefault(),this.dispatchEvent(Hd),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(_m))}function rS(i){this.enabled!==!1&&this._handleKeyDown(i)}function oS(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case oi.ROTATE:if(this.enableRotate===!1){this.state=te.NONE;break}this._handleTouchStartRotate(i),this.state=te.TOUCH_ROTATE;break;case oi.PAN:if(this.enablePan===!1){this.state=te.NONE;break}this._handleTouchStartPan(i),this.state=te.TOUCH_PAN;break;default:this.state=te.NONE}break;case 2:switch(this.touches.TWO){case oi.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=te.TOUCH_DOLLY_PAN;break;case oi.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=te.TOUCH_DOLLY_ROTATE;break;default:this.state=te.NONE}break;default:this.state=te.NONE}this.state!==te.NONE&&this.dispatchEvent(Hd)}function cS(i){switch(this._trackPointer(i),this.state){case te.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case te.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case te.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case te.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=te.NONE}}function lS(i){this.enabled!==!1&&i.preventDefault()}function hS(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function dS(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var xm,Hd,_m,xl,ym,QM,Pe,Sn,te,Vd,yl,vm=ua(()=>{bs();xm={type:"change"},Hd={type:"start"},_m={type:"end"},xl=new Kn,ym=new hn,QM=Math.cos(70*Ea.DEG2RAD),Pe=new F,Sn=2*Math.PI,te={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Vd=1e-6,yl=class extends Nr{constructor(t,e=null){super(t,e),this.state=te.NONE,this.target=new F,this.cursor=new F,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:$i.ROTATE,MIDDLE:$i.DOLLY,RIGHT:$i.PAN},this.touches={ONE:oi.ROTATE,TWO:oi.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new F,this._lastQuaternion=new Tn,this._lastTargetPosition=new F,this._quat=new Tn().setFromUnitVectors(t.up,new F(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new cs,this._sphericalDelta=new cs,this._scale=1,this._panOffset=new F,this._rotateStart=new Ct,this._rotateEnd=new Ct,this._rotateDelta=new Ct,this._panStart=new Ct,this._panEnd=new Ct,this._panDelta=new Ct,this._dollyStart=new Ct,this._dollyEnd=new Ct,this._dollyDelta=new Ct,this._dollyDirection=new F,this._mouse=new Ct,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=eS.bind(this),this._onPointerDown=tS.bind(this),this._onPointerUp=nS.bind(this),this._onContextMenu=lS.bind(this),this._onMouseWheel=sS.bind(this),this._onKeyDown=rS.bind(this),this._onTouchStart=oS.bind(this),this._onTouchMove=cS.bind(this),this._onMouseDown=iS.bind(this),this._onMouseMove=aS.bind(this),this._interceptControlDown=hS.bind(this),this._interceptControlUp=dS.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(t){this._cursorStyle=t,t==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(t){super.connect(t),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=te.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(t){t.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=t}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(xm),this.update(),this.state=te.NONE}pan(t,e){this._pan(t,e),this.update()}dollyIn(t){this._dollyIn(t),this.update()}dollyOut(t){this._dollyOut(t),this.update()}rotateLeft(t){this._rotateLeft(t),this.update()}rotateUp(t){this._rotateUp(t),this.update()}update(t=null){let e=this.object.position;Pe.copy(e).sub(this.target),Pe.applyQuaternion(this._quat),this._spherical.setFromVector3(Pe),this.autoRotate&&this.state===te.NONE&&this._rotateLeft(this._getAutoRotationAngle(t)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,a=this.maxAzimuthAngle;isFinite(n)&&isFinite(a)&&(n<-Math.PI?n+=Sn:n>Math.PI&&(n-=Sn),a<-Math.PI?a+=Sn:a>Math.PI&&(a-=Sn),n<=a?this._spherical.theta=Math.max(n,Math.min(a,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+a)/2?Math.max(n,this._spherical.theta):Math.min(a,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let s=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let r=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),s=r!=this._spherical.radius}if(Pe.setFromSpherical(this._spherical),Pe.applyQuaternion(this._quatInverse),e.copy(this.target).add(Pe),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let r=null;if(this.object.isPerspectiveCamera){let o=Pe.length();r=this._clampDistance(o*this._scale);let c=o-r;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),s=!!c}else if(this.object.isOrthographicCamera){let o=new F(this._mouse.x,this._mouse.y,0);o.unproject(this.object);let c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),s=c!==this.object.zoom;let l=new F(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(o),this.object.updateMatrixWorld(),r=Pe.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;r!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(r).add(this.object.position):(xl.origin.copy(this.object.position),xl.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(xl.direction))<QM?this.object.lookAt(this.target):(ym.setFromNormalAndCoplanarPoint(this.object.up,this.target),xl.intersectPlane(ym,this.target))))}else if(this.object.isOrthographicCamera){let r=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),r!==this.object.zoom&&(this.object.updateProjectionMatrix(),s=!0)}return this._scale=1,this._performCursorZoom=!1,s||this._lastPosition.distanceToSquared(this.object.position)>Vd||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Vd||this._lastTargetPosition.distanceToSquared(this.target)>Vd?(this.dispatchEvent(xm),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(t){return t!==null?Sn/60*this.autoRotateSpeed*t:Sn/60/60*this.autoRotateSpeed}_getZoomScale(t){let e=Math.abs(t*.01);return Math.pow(.95,this.zoomSpeed*e)}_rotateLeft(t){this._sphericalDelta.theta-=t}_rotateUp(t){this._sphericalDelta.phi-=t}_panLeft(t,e){Pe.setFromMatrixColumn(e,0),Pe.multiplyScalar(-t),this._panOffset.add(Pe)}_panUp(t,e){this.screenSpacePanning===!0?Pe.setFromMatrixColumn(e,1):(Pe.setFromMatrixColumn(e,0),Pe.crossVectors(this.object.up,Pe)),Pe.multiplyScalar(t),this._panOffset.add(Pe)}_pan(t,e){let n=this.domElement;if(this.object.isPerspectiveCamera){let a=this.object.position;Pe.copy(a).sub(this.target);let s=Pe.length();s*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*t*s/n.clientHeight,this.object.matrix),this._panUp(2*e*s/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(t*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(e*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(t,e){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let n=this.domElement.getBoundingClientRect(),a=t-n.left,s=e-n.top,r=n.width,o=n.height;this._mouse.x=a/r*2-1,this._mouse.y=-(s/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(t){return Math.max(this.minDistance,Math.min(this.maxDistance,t))}_handleMouseDownRotate(t){this._rotateStart.set(t.clientX,t.clientY)}_handleMouseDownDolly(t){this._updateZoomParameters(t.clientX,t.clientY),this._dollyStart.set(t.clientX,t.clientY)}_handleMouseDownPan(t){this._panStart.set(t.clientX,t.clientY)}_handleMouseMoveRotate(t){this._rotateEnd.set(t.clientX,t.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let e=this.domElement;this._rotateLeft(Sn*this._rotateDelta.x/e.clientHeight),this._rotateUp(Sn*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(t){this._dollyEnd.set(t.clientX,t.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(t){this._panEnd.set(t.clientX,t.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(t){this._updateZoomParameters(t.clientX,t.clientY),t.deltaY<0?this._dollyIn(this._getZoomScale(t.deltaY)):t.deltaY>0&&this._dollyOut(this._getZoomScale(t.deltaY)),this.update()}_handleKeyDown(t){let e=!1;switch(t.code){case this.keys.UP:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(Sn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),e=!0;break;case this.keys.BOTTOM:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(-Sn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),e=!0;break;case this.keys.LEFT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(Sn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),e=!0;break;case this.keys.RIGHT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(-Sn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),e=!0;break}e&&(t.preventDefault(),this.update())}_handleTouchStartRotate(t){if(this._pointers.length===1)this._rotateStart.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._rotateStart.set(n,a)}}_handleTouchStartPan(t){if(this._pointers.length===1)this._panStart.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._panStart.set(n,a)}}_handleTouchStartDolly(t){let e=this._getSecondPointerPosition(t),n=t.pageX-e.x,a=t.pageY-e.y,s=Math.sqrt(n*n+a*a);this._dollyStart.set(0,s)}_handleTouchStartDollyPan(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enablePan&&this._handleTouchStartPan(t)}_handleTouchStartDollyRotate(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enableRotate&&this._handleTouchStartRotate(t)}_handleTouchMoveRotate(t){if(this._pointers.length==1)this._rotateEnd.set(t.pageX,t.pageY);else{let n=this._getSecondPointerPosition(t),a=.5*(t.pageX+n.x),s=.5*(t.pageY+n.y);this._rotateEnd.set(a,s)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let e=this.domElement;this._rotateLeft(Sn*this._rotateDelta.x/e.clientHeight),this._rotateUp(Sn*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(t){if(this._pointers.length===1)this._panEnd.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._panEnd.set(n,a)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(t){let e=this._getSecondPointerPosition(t),n=t.pageX-e.x,a=t.pageY-e.y,s=Math.sqrt(n*n+a*a);this._dollyEnd.set(0,s),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let r=(t.pageX+e.x)*.5,o=(t.pageY+e.y)*.5;this._updateZoomParameters(r,o)}_handleTouchMoveDollyPan(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enablePan&&this._handleTouchMovePan(t)}_handleTouchMoveDollyRotate(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enableRotate&&this._handleTouchMoveRotate(t)}_addPointer(t){this._pointers.push(t.pointerId)}_removePointer(t){delete this._pointerPositions[t.pointerId];for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId){this._pointers.splice(e,1);return}}_isTrackingPointer(t){for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId)return!0;return!1}_trackPointer(t){let e=this._pointerPositions[t.pointerId];e===void 0&&(e=new Ct,this._pointerPositions[t.pointerId]=e),e.set(t.pageX,t.pageY)}_getSecondPointerPosition(t){let e=t.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[e]}_customWheelEvent(t){let e=t.deltaMode,n={clientX:t.clientX,clientY:t.clientY,deltaY:t.deltaY};switch(e){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return t.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}});var xs,Gd=ua(()=>{bs();ft.line={worldUnits:{value:1},linewidth:{value:1},resolution:{value:new Ct},dashOffset:{value:0},dashScale:{value:1},dashSize:{value:1},gapSize:{value:1}};gn.line={uniforms:Gr.merge([ft.common,ft.fog,ft.line]),vertexShader:`
		#include <common>
		#include <color_pars_vertex>
		#include <fog_pars_vertex>
		#include <logdepthbuf_pars_vertex>
		#include <clipping_planes_pars_vertex>

		uniform float linewidth;
		uniform vec2 resolution;

		attribute vec3 instanceStart;
		attribute vec3 instanceEnd;

		attribute vec3 instanceColorStart;
		attribute vec3 instanceColorEnd;

		#ifdef WORLD_UNITS

			varying vec4 worldPos;
			varying vec3 worldStart;
			varying vec3 worldEnd;

			#ifdef USE_DASH

				varying vec2 vUv;

			#endif

		#else

			varying vec2 vUv;

		#endif

		#ifdef USE_DASH

			uniform float dashScale;
			attribute float instanceDistanceStart;
			attribute float instanceDistanceEnd;
			varying float vLineDistance;

		#endif

		float trimSegmentAlpha( const in vec4 start, const in vec4 end ) {

			// compute the interpolation factor needed to trim the segment so it terminates
			// between the camera plane and the near plane

			// conservative estimate of the near plane
			float a = projectionMatrix[ 2 ][ 2 ]; // 3nd entry in 3th column
			float b = projectionMatrix[ 3 ][ 2 ]; // 3nd entry in 4th column

			// we need different nearEstimate formula for reversed and default depth buffer
			// a is positive with a reversed depth buffer so it can be used for controlling the code flow
			float nearEstimate = ( a > 0.0 ) ? ( - b / ( a + 1.0 ) ) : ( - 0.5 * b / a );

			return ( nearEstimate - start.z ) / ( end.z - start.z );

		}

		void main() {

			#ifdef USE_COLOR

				vColor.xyz = ( position.y < 0.5 ) ? instanceColorStart : instanceColorEnd;

			#endif

			float aspect = resolution.x / resolution.y;

			// camera space
			vec4 start = modelViewMatrix * vec4( instanceStart, 1.0 );
			vec4 end = modelViewMatrix * vec4( instanceEnd, 1.0 );

			#ifdef USE_DASH

				float lineDistanceStart = dashScale * instanceDistanceStart;
				float lineDistanceEnd = dashScale * instanceDistanceEnd;

			#endif

			#ifdef WORLD_UNITS

				worldStart = start.xyz;
				worldEnd = end.xyz;

			#else

				vUv = uv;

			#endif

			// special case for perspective projection, and segments that terminate either in, or behind, the camera plane
			// clearly the gpu firmware has a way of addressing this issue when projecting into ndc space
			// but we need to perform ndc-space calculations in the shader, so we must address this issue directly
			// perhaps there is a more elegant solution -- WestLangley

			bool perspective = ( projectionMatrix[ 2 ][ 3 ] == - 1.0 ); // 4th entry in the 3rd column

			if ( perspective ) {

				if ( start.z < 0.0 && end.z >= 0.0 ) {

					float alpha = trimSegmentAlpha( start, end );
					end.xyz = mix( start.xyz, end.xyz, alpha );

					#ifdef USE_DASH

						lineDistanceEnd = mix( lineDistanceStart, lineDistanceEnd, alpha );

					#endif

				} else if ( end.z < 0.0 && start.z >= 0.0 ) {

					float alpha = trimSegmentAlpha( end, start );
					start.xyz = mix( end.xyz, start.xyz, alpha );

					#ifdef USE_DASH

						lineDistanceStart = mix( lineDistanceEnd, lineDistanceStart, alpha );

					#endif

				}

			}

			#ifdef USE_DASH

				vLineDistance = ( position.y < 0.5 ) ? lineDistanceStart : lineDistanceEnd;
				vUv = uv;

			#endif

			// clip space
			vec4 clipStart = projectionMatrix * start;
			vec4 clipEnd = projectionMatrix * end;

			// ndc space
			vec3 ndcStart = clipStart.xyz / clipStart.w;
			vec3 ndcEnd = clipEnd.xyz / clipEnd.w;

			// direction
			vec2 dir = ndcEnd.xy - ndcStart.xy;

			// account for clip-space aspect ratio
			dir.x *= aspect;
			dir = normalize( dir );

			#ifdef WORLD_UNITS

				vec3 worldDir = normalize( end.xyz - start.xyz );
				vec3 tmpFwd = perspective ? normalize( mix( start.xyz, end.xyz, 0.5 ) ) : vec3( 0.0, 0.0, - 1.0 );
				vec3 worldUp = normalize( cross( worldDir, tmpFwd ) );
				vec3 worldFwd = cross( worldDir, worldUp );
				worldPos = position.y < 0.5 ? start: end;

				// height offset
				float hw = linewidth * 0.5;
				worldPos.xyz += position.x < 0.0 ? hw * worldUp : - hw * worldUp;

				// don't extend the line if we're rendering dashes because we
				// won't be rendering the endcaps
				#ifndef USE_DASH

					// cap extension
					worldPos.xyz += position.y < 0.5 ? - hw * worldDir : hw * worldDir;

					// add width to the box
					worldPos.xyz += worldFwd * hw;

					// endcaps
					if ( position.y > 1.0 || position.y < 0.0 ) {

						worldPos.xyz -= worldFwd * 2.0 * hw;

					}

				#endif

				// project the worldpos
				vec4 clip = projectionMatrix * worldPos;

				// shift the depth of the projected points so the line
				// segments overlap neatly
				vec3 clipPose = ( position.y < 0.5 ) ? ndcStart : ndcEnd;

				// only shift the depth of vertices in front of the camera (#35137)
				if ( clip.w > 0.0 ) clip.z = clipPose.z * clip.w;

			#else

				vec2 offset = vec2( dir.y, - dir.x );
				// undo aspect ratio adjustment
				dir.x /= aspect;
				offset.x /= aspect;

				// sign flip
				if ( position.x < 0.0 ) offset *= - 1.0;

				// endcaps
				if ( position.y < 0.0 ) {

					offset += - dir;

				} else if ( position.y > 1.0 ) {

					offset += dir;

				}

				// adjust for linewidth
				offset *= linewidth;

				// adjust for clip-space to screen-space conversion // maybe resolution should be based on viewport ...
				offset /= resolution.y;

				// select end
				vec4 clip = ( position.y < 0.5 ) ? clipStart : clipEnd;

				// back to clip space
				offset *= clip.w;

				clip.xy += offset;

			#endif

			gl_Position = clip;

			vec4 mvPosition = ( position.y < 0.5 ) ? start : end; // this is an approximation

			#include <logdepthbuf_vertex>
			#include <clipping_planes_vertex>
			#include <fog_vertex>

		}
		`,fragmentShader:`
		uniform vec3 diffuse;
		uniform float opacity;
		uniform float linewidth;

		#ifdef USE_DASH

			uniform float dashOffset;
			uniform float dashSize;
			uniform float gapSize;

		#endif

		varying float vLineDistance;

		#ifdef WORLD_UNITS

			varying vec4 worldPos;
			varying vec3 worldStart;
			varying vec3 worldEnd;

			#ifdef USE_DASH

				varying vec2 vUv;

			#endif

		#else

			varying vec2 vUv;

		#endif

		#include <common>
		#include <color_pars_fragment>
		#include <fog_pars_fragment>
		#include <logdepthbuf_pars_fragment>
		#include <clipping_planes_pars_fragment>

		vec2 closestLineToLine(vec3 p1, vec3 p2, vec3 p3, vec3 p4) {

			float mua;
			float mub;

			vec3 p13 = p1 - p3;
			vec3 p43 = p4 - p3;

			vec3 p21 = p2 - p1;

			float d1343 = dot( p13, p43 );
			float d4321 = dot( p43, p21 );
			float d1321 = dot( p13, p21 );
			float d4343 = dot( p43, p43 );
			float d2121 = dot( p21, p21 );

			float denom = d2121 * d4343 - d4321 * d4321;

			float numer = d1343 * d4321 - d1321 * d4343;

			mua = numer / denom;
			mua = clamp( mua, 0.0, 1.0 );
			mub = ( d1343 + d4321 * ( mua ) ) / d4343;
			mub = clamp( mub, 0.0, 1.0 );

			return vec2( mua, mub );

		}

		void main() {

			float alpha = opacity;
			vec4 diffuseColor = vec4( diffuse, alpha );

			#include <clipping_planes_fragment>

			#ifdef USE_DASH

				if ( vUv.y < - 1.0 || vUv.y > 1.0 ) discard; // discard endcaps

				if ( mod( vLineDistance + dashOffset, dashSize + gapSize ) > dashSize ) discard; // todo - FIX

			#endif

			#ifdef WORLD_UNITS

				float len;

				if ( isOrthographic ) {

					// View rays are parallel to the z axis so the distance reduces to camera-space XY
					vec2 lineDir = worldEnd.xy - worldStart.xy;
					float t = clamp( dot( worldPos.xy - worldStart.xy, lineDir ) / dot( lineDir, lineDir ), 0.0, 1.0 );
					len = length( worldStart.xy + lineDir * t - worldPos.xy );

				} else {

					// Find the closest points on the view ray and the line segment
					vec3 rayEnd = normalize( worldPos.xyz ) * 1e5;
					vec3 lineDir = worldEnd - worldStart;
					vec2 params = closestLineToLine( worldStart, worldEnd, vec3( 0.0, 0.0, 0.0 ), rayEnd );

					vec3 p1 = worldStart + lineDir * params.x;
					vec3 p2 = rayEnd * params.y;
					vec3 delta = p1 - p2;
					len = length( delta );

				}

				float norm = len / linewidth;

				#ifndef USE_DASH

					#ifdef USE_ALPHA_TO_COVERAGE

						float dnorm = fwidth( norm );
						alpha = 1.0 - smoothstep( 0.5 - dnorm, 0.5 + dnorm, norm );

					#else

						if ( norm > 0.5 ) {

							discard;

						}

					#endif

				#endif

			#else

				#ifdef USE_ALPHA_TO_COVERAGE

					// artifacts appear on some hardware if a derivative is taken within a conditional
					float a = vUv.x;
					float b = ( vUv.y > 0.0 ) ? vUv.y - 1.0 : vUv.y + 1.0;
					float len2 = a * a + b * b;
					float dlen = fwidth( len2 );

					if ( abs( vUv.y ) > 1.0 ) {

						alpha = 1.0 - smoothstep( 1.0 - dlen, 1.0 + dlen, len2 );

					}

				#else

					if ( abs( vUv.y ) > 1.0 ) {

						float a = vUv.x;
						float b = ( vUv.y > 0.0 ) ? vUv.y - 1.0 : vUv.y + 1.0;
						float len2 = a * a + b * b;

						if ( len2 > 1.0 ) discard;

					}

				#endif

			#endif

			#include <logdepthbuf_fragment>
			#include <color_fragment>

			gl_FragColor = vec4( diffuseColor.rgb, alpha );

			#include <tonemapping_fragment>
			#include <colorspace_fragment>
			#include <fog_fragment>
			#include <premultiplied_alpha_fragment>

		}
		`};xs=class extends Bn{constructor(t){super({type:"LineMaterial",uniforms:Gr.clone(gn.line.uniforms),vertexShader:gn.line.vertexShader,fragmentShader:gn.line.fragmentShader,clipping:!0}),this.isLineMaterial=!0,this.setValues(t)}get color(){return this.uniforms.diffuse.value}set color(t){this.uniforms.diffuse.value=t}get worldUnits(){return"WORLD_UNITS"in this.defines}set worldUnits(t){t===!0!==this.worldUnits&&(this.needsUpdate=!0),t===!0?this.defines.WORLD_UNITS="":delete this.defines.WORLD_UNITS}get linewidth(){return this.uniforms.linewidth.value}set linewidth(t){this.uniforms.linewidth&&(this.uniforms.linewidth.value=t)}get dashed(){return"USE_DASH"in this.defines}set dashed(t){t===!0!==this.dashed&&(this.needsUpdate=!0),t===!0?this.defines.USE_DASH="":delete this.defines.USE_DASH}get dashScale(){return this.uniforms.dashScale.value}set dashScale(t){this.uniforms.dashScale.value=t}get dashSize(){return this.uniforms.dashSize.value}set dashSize(t){this.uniforms.dashSize.value=t}get dashOffset(){return this.uniforms.dashOffset.value}set dashOffset(t){this.uniforms.dashOffset.value=t}get gapSize(){return this.uniforms.gapSize.value}set gapSize(t){this.uniforms.gapSize.value=t}get opacity(){return this.uniforms.opacity.value}set opacity(t){this.uniforms&&(this.uniforms.opacity.value=t)}get resolution(){return this.uniforms.resolution.value}set resolution(t){this.uniforms.resolution.value.copy(t)}get alphaToCoverage(){return"USE_ALPHA_TO_COVERAGE"in this.defines}set alphaToCoverage(t){this.defines&&(t===!0!==this.alphaToCoverage&&(this.needsUpdate=!0),t===!0?this.defines.USE_ALPHA_TO_COVERAGE="":delete this.defines.USE_ALPHA_TO_COVERAGE)}}});var Mm,_l,ys,Wd=ua(()=>{bs();Mm=new Ie,_l=new F,ys=class extends Ir{constructor(){super(),this.isLineSegmentsGeometry=!0,this.type="LineSegmentsGeometry";let t=[-1,2,0,1,2,0,-1,1,0,1,1,0,-1,0,0,1,0,0,-1,-1,0,1,-1,0],e=[-1,2,1,2,-1,1,1,1,-1,-1,1,-1,-1,-2,1,-2],n=[0,2,1,2,3,1,2,4,3,4,5,3,4,6,5,6,7,5];this.setIndex(n),this.setAttribute("position",new re(t,3)),this.setAttribute("uv",new re(e,2))}applyMatrix4(t){let e=this.attributes.instanceStart,n=this.attributes.instanceEnd;return e!==void 0&&(e.applyMatrix4(t),n.applyMatrix4(t),e.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this}setPositions(t){let e;t instanceof Float32Array?e=t:Array.isArray(t)&&(e=new Float32Array(t));let n=new Zi(e,6,1);return this.setAttribute("instanceStart",new Jn(n,3,0)),this.setAttribute("instanceEnd",new Jn(n,3,3)),this.instanceCount=this.attributes.instanceStart.count,this.computeBoundingBox(),this.computeBoundingSphere(),this}setColors(t){let e;t instanceof Float32Array?e=t:Array.isArray(t)&&(e=new Float32Array(t));let n=new Zi(e,6,1);return this.setAttribute("instanceColorStart",new Jn(n,3,0)),this.setAttribute("instanceColorEnd",new Jn(n,3,3)),this}fromWireframeGeometry(t){return this.setPositions(t.attributes.position.array),this}fromEdgesGeometry(t){return this.setPositions(t.attributes.position.array),this}fromMesh(t){return this.fromWireframeGeometry(new _r(t.geometry)),this}fromLineSegments(t){let e=t.geometry;return this.setPositions(e.attributes.position.array),this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ie);let t=this.attributes.instanceStart,e=this.attributes.instanceEnd;t!==void 0&&e!==void 0&&(this.boundingBox.setFromBufferAttribute(t),Mm.setFromBufferAttribute(e),this.boundingBox.union(Mm))}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new ze),this.boundingBox===null&&this.computeBoundingBox();let t=this.attributes.instanceStart,e=this.attributes.instanceEnd;if(t!==void 0&&e!==void 0){let n=this.boundingSphere.center;this.boundingBox.getCenter(n);let a=0;for(let s=0,r=t.count;s<r;s++)_l.fromBufferAttribute(t,s),a=Math.max(a,n.distanceToSquared(_l)),_l.fromBufferAttribute(e,s),a=Math.max(a,n.distanceToSquared(_l));this.boundingSphere.radius=Math.sqrt(a),isNaN(this.boundingSphere.radius)&&console.error("THREE.LineSegmentsGeometry.computeBoundingSphere(): Computed radius is NaN. The instanced position data is likely to have NaN values.",this)}}toJSON(){}}});function Em(i,t,e){return fi.set(0,0,-t,1).applyMatrix4(i.projectionMatrix),fi.multiplyScalar(1/fi.w),fi.x=Ia/e.width,fi.y=Ia/e.height,fi.applyMatrix4(i.projectionMatrixInverse),fi.multiplyScalar(1/fi.w),Math.abs(Math.max(fi.x,fi.y))}function uS(i,t){let e=i.matrixWorld,n=i.geometry,a=n.attributes.instanceStart,s=n.attributes.instanceEnd,r=Math.min(n.instanceCount,a.count);for(let o=0,c=r;o<c;o++){Xe.start.fromBufferAttribute(a,o),Xe.end.fromBufferAttribute(s,o),Xe.applyMatrix4(e);let l=new F,h=new F;pi.distanceSqToSegment(Xe.start,Xe.end,h,l),h.distanceTo(l)<Ia*.5&&t.push({point:h,pointOnLine:l,distance:pi.origin.distanceTo(h),object:i,face:null,faceIndex:o,uv:null,uv1:null})}}function fS(i,t,e){let n=t.projectionMatrix,s=i.material.resolution,r=i.matrixWorld,o=i.geometry,c=o.attributes.instanceStart,l=o.attributes.instanceEnd,h=Math.min(o.instanceCount,c.count),u=-t.near;pi.at(1,ui),ui.w=1,ui.applyMatrix4(t.matrixWorldInverse),ui.applyMatrix4(n),ui.multiplyScalar(1/ui.w),ui.x*=s.x/2,ui.y*=s.y/2,ui.z=0,Xd.copy(ui),qd.multiplyMatrices(t.matrixWorldInverse,r);for(let d=0,f=h;d<f;d++){if(We.fromBufferAttribute(c,d),je.fromBufferAttribute(l,d),We.w=1,je.w=1,We.applyMatrix4(qd),je.applyMatrix4(qd),We.z>u&&je.z>u)continue;if(We.z>u){let w=We.z-je.z,p=(We.z-u)/w;We.lerp(je,p)}else if(je.z>u){let w=je.z-We.z,p=(je.z-u)/w;je.lerp(We,p)}We.applyMatrix4(n),je.applyMatrix4(n),We.multiplyScalar(1/We.w),je.multiplyScalar(1/je.w),We.x*=s.x/2,We.y*=s.y/2,je.x*=s.x/2,je.y*=s.y/2,Xe.start.copy(We),Xe.start.z=0,Xe.end.copy(je),Xe.end.z=0;let y=Xe.closestPointToPointParameter(Xd,!0);Xe.at(y,Am);let g=Ea.lerp(We.z,je.z,y),b=g>=-1&&g<=1,v=Xd.distanceTo(Am)<Ia*.5;if(b&&v){Xe.start.fromBufferAttribute(c,d),Xe.end.fromBufferAttribute(l,d),Xe.start.applyMatrix4(r),Xe.end.applyMatrix4(r);let w=new F,p=new F;pi.distanceSqToSegment(Xe.start,Xe.end,p,w),e.push({point:p,pointOnLine:w,distance:pi.origin.distanceTo(p),object:i,face:null,faceIndex:d,uv:null,uv1:null})}}}var jd,Sm,wm,We,je,ui,Xd,qd,Xe,Am,vl,Ml,fi,pi,Ia,Sl,Tm=ua(()=>{bs();Wd();Gd();jd=new $t,Sm=new F,wm=new F,We=new $t,je=new $t,ui=new $t,Xd=new F,qd=new Zt,Xe=new _a,Am=new F,vl=new Ie,Ml=new ze,fi=new $t;Sl=class extends tn{constructor(t=new ys,e=new xs({color:Math.random()*16777215})){super(t,e),this.isLineSegments2=!0,this.type="LineSegments2"}computeLineDistances(){let t=this.geometry,e=t.attributes.instanceStart,n=t.attributes.instanceEnd,a=new Float32Array(2*e.count);for(let r=0,o=0,c=e.count;r<c;r++,o+=2)Sm.fromBufferAttribute(e,r),wm.fromBufferAttribute(n,r),a[o]=o===0?0:a[o-1],a[o+1]=a[o]+Sm.distanceTo(wm);let s=new Zi(a,2,1);return t.setAttribute("instanceDistanceStart",new Jn(s,1,0)),t.setAttribute("instanceDistanceEnd",new Jn(s,1,1)),this}raycast(t,e){let n=this.material.worldUnits,a=t.camera;if(a===null&&!n&&console.error('LineSegments2: "Raycaster.camera" needs to be set in order to raycast against LineSegments2 while worldUnits is set to false.'),n===!1&&(this.material.resolution.x===0||this.material.resolution.y===0))return;let s=t.params.Line2!==void 0&&t.params.Line2.threshold||0;pi=t.ray;let r=this.matrixWorld,o=this.geometry,c=this.material;Ia=c.linewidth+s,o.boundingSphere===null&&o.computeBoundingSphere(),Ml.copy(o.boundingSphere).applyMatrix4(r);let l;if(n)l=Ia*.5;else{let u=Math.max(a.near,Ml.distanceToPoint(pi.origin));l=Em(a,u,c.resolution)}if(Ml.radius+=l,pi.intersectsSphere(Ml)===!1)return;o.boundingBox===null&&o.computeBoundingBox(),vl.copy(o.boundingBox).applyMatrix4(r);let h;if(n)h=Ia*.5;else{let u=Math.max(a.near,vl.distanceToPoint(pi.origin));h=Em(a,u,c.resolution)}vl.expandByScalar(h),pi.intersectsBox(vl)!==!1&&(n?uS(this,e):fS(this,a,e))}onBeforeRender(t){let e=this.material.uniforms;e&&e.resolution&&(t.getViewport(jd),this.material.uniforms.resolution.value.set(jd.z,jd.w))}}});var _s={};$u(_s,{AmbientLight:()=>Tr,BackSide:()=>Ge,BatchedMesh:()=>hr,Box3:()=>Ie,BufferAttribute:()=>un,BufferGeometry:()=>Ae,ByteType:()=>Dr,Color:()=>kt,ConeGeometry:()=>gr,CylinderGeometry:()=>rs,DataTexture:()=>Ti,DirectionalLight:()=>Er,DoubleSide:()=>kn,FloatType:()=>pn,FrontSide:()=>ci,GridHelper:()=>Cr,Group:()=>Ai,IntType:()=>us,Line:()=>ya,Line3:()=>_a,LineBasicMaterial:()=>xa,LineLoop:()=>dr,LineMaterial:()=>xs,LineSegments:()=>as,LineSegments2:()=>Sl,LineSegmentsGeometry:()=>ys,MathUtils:()=>Ea,Matrix3:()=>Dt,Matrix4:()=>Zt,Mesh:()=>tn,MeshBasicMaterial:()=>is,MeshLambertMaterial:()=>vr,NearestFilter:()=>we,Object3D:()=>Re,OrbitControls:()=>yl,PerspectiveCamera:()=>dn,Plane:()=>hn,Points:()=>ur,REVISION:()=>Tc,RGBAFormat:()=>mn,RGBAIntegerFormat:()=>ps,RGFormat:()=>hi,RGIntegerFormat:()=>fs,Ray:()=>Kn,Raycaster:()=>Rr,RedFormat:()=>Or,RedIntegerFormat:()=>Aa,Scene:()=>rr,ShortType:()=>Ur,Sphere:()=>ze,SphereGeometry:()=>xr,TOUCH:()=>oi,TorusGeometry:()=>yr,Triangle:()=>ai,UnsignedByteType:()=>en,UnsignedIntType:()=>Mn,UnsignedShortType:()=>Qi,Vector2:()=>Ct,Vector3:()=>F,Vector4:()=>$t,WebGLRenderer:()=>ml});var vs=ua(()=>{bs();vm();Gd();Tm();Wd()});var fA={};$u(fA,{default:()=>uA,explorer:()=>lu,mesh:()=>zu});function xt(i,t,e){let n=document.createElement(i);return t&&(n.className=t),e!==void 0&&(n.textContent=e),n}function Fe(i,t,e){let n=Object.entries(t);for(let[a,s]of n)i.addEventListener(a,s,e);return()=>{for(let[a,s]of n)i.removeEventListener(a,s,e)}}function po(i,t){let e=xt("div",i);return e.setAttribute("role","toolbar"),e.setAttribute("aria-label",t),e}function Be(i,t){let e=String(t);i.textContent!==e&&(i.textContent=e)}function xe(i,t,e){let n=String(e);i.getAttribute(t)!==n&&i.setAttribute(t,n)}function Wn(i,t){i.hidden!==!!t&&(i.hidden=!!t)}var Qu=new WeakMap;function zi(i,t,e){let n=Qu.get(i);n||Qu.set(i,n={}),n[t]!==e&&(n[t]=e,i.style[t]=e)}function mo(i,t,e=document){let n=URL.createObjectURL(i),a=e.createElement("a");a.href=n,a.download=t,a.hidden=!0,e.body.append(a),a.click(),a.remove(),setTimeout(()=>URL.revokeObjectURL(n),0)}var tf=.32,jb=.55,Xb=.12,qb=440,oh=[400,6400],ch=[.08,.2];function Yb(i){if(!Array.isArray(i)||i.length!==3)return null;let t=Math.max(...i.map(a=>Math.abs(Number(a))));if(!(t>0))return null;let e=i.map(a=>Number.isFinite(t)?Number(a)/t:Math.abs(a)===1/0?Math.sign(a):0),n=Math.sqrt(e[0]*e[0]+e[1]*e[1]+e[2]*e[2]);return e.map(a=>a/n)}function lh(i){let t=Yb(i);if(!t)return null;let[e,n,a]=t,s=(a+1)/2;return{pan:e,frequency:qb*2**n,cutoff:oh[0]*(oh[1]/oh[0])**s,gain:ch[0]+(ch[1]-ch[0])*s}}function Jb(i){let t=i||{};return[["U",lh(t.u),tf],["V",lh(t.v),tf],["N",lh(t.unit_normal),jb]].filter(([,e])=>e)}function Kb(i,t){let e=[],n=i.currentTime+.02;for(let[,a,s]of t){let r=i.createOscillator();r.type="sawtooth",r.frequency.setValueAtTime(a.frequency,n);let o=i.createBiquadFilter();o.type="lowpass",o.frequency.setValueAtTime(a.cutoff,n);let c=i.createGain();c.gain.setValueAtTime(0,n),c.gain.linearRampToValueAtTime(a.gain,n+.02),c.gain.setValueAtTime(a.gain,n+s-.06),c.gain.linearRampToValueAtTime(0,n+s);let l=i.createStereoPanner();l.pan.setValueAtTime(a.pan,n),r.connect(o).connect(c).connect(l).connect(i.destination),r.start(n),r.stop(n+s),e.push(r),n+=s+Xb}return e}function ef(i,t){let e=xt("button","tnx-listen tn-text-button","♪ Listen");e.type="button";let n="Listen to U, V and N: pan follows x, pitch follows y, brightness follows z";e.setAttribute("aria-label",n),e.title=n,xe(e,"aria-pressed",!1),i.appendChild(e);let a=null,s=!1,r=[];function o(){if(!s)return;let c=window.AudioContext||window.webkitAudioContext;if(c){a||(a=new c),a.state==="suspended"&&a.resume();for(let l of r)l.stop();r=Kb(a,Jb(t()))}}return e.addEventListener("click",()=>{s=!s,xe(e,"aria-pressed",s),s?o():a&&a.suspend()}),{changed:o,dispose(){e.remove(),a&&a.close()}}}var af=(i,t)=>(t?"−":"+")+"xyz"[i],nf=(i,t)=>i===2?t?"down":"up":"towards "+af(i,t),go=i=>i.length===1?i[0]:i.slice(0,-1).join(", ")+" and "+i[i.length-1],Zb=i=>i<.5?"less than 1":String(Math.round(i));function $b(i){let t=i.map(Number),e=t.map(Math.abs),n=[0,1,2].map(d=>af(d,t[d]<0)),a=[0,1,2].sort((d,f)=>e[f]-e[d]),s=a[0];if(e[a[1]]===0&&e[a[2]]===0)return`N points straight ${nf(s,t[s]<0)}, along ${n[s]}.`;let r=a.filter(d=>e[d]>=.05).map(d=>(e[d]<.25?"a little ":"")+nf(d,t[d]<0)),o=[0,1,2].filter(d=>e[d]===e[s]),c=[0,1,2].filter(d=>d!==s).map(d=>e[d]),l=Math.atan2(Math.sqrt(c[0]*c[0]+c[1]*c[1]),e[s]),h=Zb(l*(180/Math.PI)),u;return o.length===1?u=`mostly ${n[s]}, ${h}° from the ${"xyz"[s]} axis`:o.length===2?u=`equally ${go(o.map(d=>n[d]))}, ${h}° from the ${go(o.map(d=>"xyz"[d]))} axes`:u=`equally ${go(n)}, ${h}° from each axis`,`N points ${go(r)}: ${u}.`}function Qb(i,t,e){let n=e?e.map(Number):null,a=n?Math.sqrt(n[0]*n[0]+n[1]*n[1]+n[2]*n[2]):0;if(!n||!(a>0)||!Number.isFinite(a))return`From its front (the side N points to), ${t} turns counter-clockwise.`;let s=i.map(Number),r=(n[0]*s[0]+n[1]*s[1]+n[2]*s[2])/a;if(Math.abs(r)<.02)return"You see the triangle edge-on: neither side faces you.";let[o,c]=r>0?["front of the triangle (N points towards you)","counter-clockwise"]:["back of the triangle (N points away from you)","clockwise"];return`You see the ${o}, and ${t} turns ${c}.`}function sf(i,t,e){let n=i||{};if(n.ok===!1)return`Nothing to describe: ${n.error||n.status||""}`.trim();if(n.degenerate||!Array.isArray(n.unit_normal))return`${n.status||""} No direction to describe: the triangle has no front or back.`.trim();let a=t==="ACB"?"A→C→B":"A→B→C";return`${$b(n.unit_normal)} ${Qb(n.unit_normal,a,e)}`}var tx=0;function rf(i){i.tabIndex=0,i.setAttribute("role","group"),i.setAttribute("aria-label","The model in 3D. Arrow keys turn it, + and − zoom, Home resets the view.")}function bo(i,t){return Fe(i,{keydown:n=>{if(n.target!==i||n.altKey||n.ctrlKey||n.metaKey)return;let a=(n.shiftKey?45:15)*(Math.PI/180),s={ArrowLeft:()=>t.turn(-a,0),ArrowRight:()=>t.turn(a,0),ArrowUp:()=>t.turn(0,a),ArrowDown:()=>t.turn(0,-a),"+":()=>t.zoom(.8),"=":()=>t.zoom(.8),"-":()=>t.zoom(1.25),Home:()=>t.reset()};s[n.key]&&(n.preventDefault(),s[n.key]())}})}function of({onPick:i,picked:t}){let e=xt("form","tnm-keys"),n=`tnm-face-${++tx}`,a=xt("label","tnm-face-label","Face number");a.htmlFor=n;let s=xt("input","tnm-face-input");Object.assign(s,{id:n,type:"number",min:"0",step:"1",inputMode:"numeric",autocomplete:"off"});let r=xt("button","tnm-button tn-text-button","Show face");r.type="submit";let o=xt("button","tnm-button tn-text-button","Previous face to flip"),c=xt("button","tnm-button tn-text-button","Next face to flip");o.type=c.type="button",e.append(a,s,r,o,c);let l=null;function h(){let d=s.value.trim();if(!d||!s.checkValidity()){s.reportValidity();return}i(Number(d))}e.addEventListener("submit",d=>{d.preventDefault(),h()}),s.addEventListener("keydown",d=>{d.key==="Enter"&&(d.preventDefault(),h())});function u(d){if(!l||!l.length)return;let f=t(),m=d>0?l.findIndex(y=>y>f):l.findLastIndex(y=>y<f);m<0&&(m=d>0?0:l.length-1),s.value=String(l[m]),i(l[m])}return o.addEventListener("click",()=>u(-1)),c.addEventListener("click",()=>u(1)),{form:e,update(d,f){l=f||null,a.textContent=d?`Face number (0 to ${d-1})`:"Face number",o.hidden=c.hidden=!(l&&l.length)},showPicked(d){s.ownerDocument.activeElement!==s&&(s.value=String(d))}}}var cf=".tn-view{--tn-bg: #fff;--tn-fg: #1a1a1a;--tn-muted: #4a4f5c;font:15px/1.4 system-ui,-apple-system,Segoe UI,Roboto,sans-serif;color:var(--tn-fg);max-width:100%}.tn-view.tn-dark{--tn-bg: #1b1d24;--tn-fg: #f2f2f2;--tn-muted: #c3c7d1}.tn-view.tn-fullscreen{position:fixed;inset:0;z-index:10000;width:100vw;height:100vh;max-width:none;box-sizing:border-box;padding:8px;background:var(--tn-bg)}.tn-fullscreen .tn-stage{flex:1 1 auto;height:auto;max-height:none}.tn-text-button{font:inherit;font-size:14px;line-height:1.2;border-radius:6px;cursor:pointer;border:1px solid var(--tn-muted);background:var(--tn-bg);color:var(--tn-fg)}.tn-text-button[aria-pressed=true]{background:var(--tn-fg);color:var(--tn-bg)}.tn-present{position:absolute;top:6px;right:6px;z-index:20;display:flex;gap:4px}.tn-present-button{display:flex;align-items:center;justify-content:center;width:34px;height:34px;padding:0;border:1px solid var(--tn-muted);border-radius:6px;background:var(--tn-bg);color:var(--tn-fg);cursor:pointer}.tn-present-button svg{width:22px;height:22px;fill:none;stroke:currentColor;stroke-width:2;stroke-linecap:round;stroke-linejoin:round}.tn-text-button:focus-visible,.tn-present-button:focus-visible{outline:3px solid #0072B2;outline-offset:2px}";function Vi(i,t,e){for(let[n,a]of[["trinormal-view-base",cf],[t,e]]){if(i.getElementById(n))continue;let s=i.createElement("style");s.id=n,s.textContent=a,i.head.appendChild(s)}}var xo=".tnx-describe,.tnm-describe{margin:6px 0 0;padding:4px 8px;font-size:15px;color:var(--tn-fg);border-left:4px solid #0072B2}.tnx-exact,.tnx-decimals select,.tnm-face-input{min-height:28px;box-sizing:border-box}.tnx-slider{min-height:24px}.tnx-listen{margin:6px 0 0;padding:5px 9px;min-height:32px}@media(forced-colors:active){.tn-view button,.tnx-exact,.tnx-decimals select,.tnm-face-input{border:1px solid ButtonText}.tnx-toolbar button[aria-pressed=true],.tn-text-button[aria-pressed=true]{forced-color-adjust:none;background:Highlight;color:HighlightText;border-color:Highlight}.tn-view :focus-visible{outline:3px solid Highlight;outline-offset:2px}.tnx-vertex,.tnx-stage,.tnm-stage{border-color:CanvasText}.tnx-describe,.tnm-describe{border-left-color:CanvasText}}@media(prefers-reduced-motion:reduce){.tn-view *,.tn-view *:before,.tn-view *:after{transition:none!important;animation:none!important}}";var hh=250,ix=0;function ax(i){let t=i.display;if(!t)return null;let e=t.A.clone().add(t.B).add(t.C).divideScalar(3),n=i.stage.camera.position.clone().sub(e);return[n.x,n.y,n.z]}function lf(i){let{model:t,stage:e,stageEl:n}=i;Vi(n.ownerDocument||document,"trinormal-access-style",xo);let a=xt("div","tnx-access"),s=xt("p","tnx-describe");s.id=`tnx-describe-${++ix}`,s.setAttribute("role","status"),s.setAttribute("aria-live","polite"),a.append(s),i.side.insertBefore(a,i.hint),n.setAttribute("role","group"),n.setAttribute("aria-label","3D view of the triangle ABC and its normal N. Arrow keys turn it, + and − zoom, Home resets the view."),n.tabIndex=0,n.dataset.lmSuppressShortcuts="true";let r=bo(n,e);xe(n,"aria-describedby",s.id),e.canvas.setAttribute("aria-hidden","true");let o=ef(a,()=>t.get("state")),c=0,l=null,h="";function u(){c=0;let m=t.get("state"),y=ax(i);Be(s,sf(m,t.get("winding"),y)),y&&String(y)!==h&&(h=String(y),t.send({viewer:y})),m!==l&&(l=m,o.changed())}function d(){clearTimeout(c),c=setTimeout(u,hh)}let f=["state","winding"];for(let m of f)t.on("change:"+m,d);return e.controls.addEventListener("change",d),u(),l=t.get("state"),()=>{clearTimeout(c);for(let m of f)t.off("change:"+m,d);e.controls.removeEventListener("change",d),r(),o.dispose(),a.remove()}}var sx=/^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/,rx=/^([+-]?\d+)\s*\/\s*([+-]?\d+)$/;function Hi(i){let t=String(i??"").trim();if(sx.test(t))return Number(t);let e=rx.exec(t);if(e){let n=Number(e[1])/Number(e[2]);return Number.isFinite(n)?n:NaN}return NaN}function hf(i){if(!Array.isArray(i)||i.length!==3)return null;let t=i.map(Hi);return t.every(Number.isFinite)?t:null}function Gs(i){let t=String(i??"0.1").trim(),e=/^(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/.exec(t);if(!e||!(Number(t)>0)||!/\d/.test((e[1]||"")+(e[2]||"")))return{value:.1,decimals:1,units:1};let n=((e[1]||"")+(e[2]||"")).replace(/^0+(?=\d)/,""),a=Number(e[3]||0)-(e[2]||"").length;for(;n.length>1&&n.endsWith("0");)n=n.slice(0,-1),a+=1;let s=Math.max(0,-a),r=Number(n)*10**(a+s);return{value:r/10**s,decimals:s,units:r}}function ox(i){let t=new DataView(new ArrayBuffer(8));t.setFloat64(0,i);let e=t.getBigUint64(0),n=e>>63n===1n,a=Number(e>>52n&0x7ffn),s=e&(1n<<52n)-1n;a&&(s|=1n<<52n);let r=(a||1)-1075,o=n?-s:s;return r>=0?[o<<BigInt(r),1n]:[o,1n<<BigInt(-r)]}function cx(i,t){if(!Number.isFinite(i))return 0;let[e,n]=ox(i),a=10n**BigInt(t.decimals),s=BigInt(t.units),o=((e<0n?-e:e)*a*2n+n*s)/(2n*n*s);return Number(e<0n?-o:o)}function Ws(i,t,e){let n=cx(i,t);if(Array.isArray(e)&&e.length===2){let a=Math.ceil(Number(e[0])/t.value-1e-9),s=Math.floor(Number(e[1])/t.value+1e-9);Number.isFinite(a)&&(n=Math.max(n,a)),Number.isFinite(s)&&(n=Math.min(n,s))}return n===0?0:n}function dh(i,t,e){return Math.abs(i-t*e.value)<=1e-9*Math.max(1,Math.abs(i))}function js(i,t){let e=BigInt(i)*BigInt(t.units),n=e<0n,a=(n?-e:e).toString();return t.decimals>0&&(a=a.padStart(t.decimals+1,"0"),a=a.slice(0,-t.decimals)+"."+a.slice(-t.decimals)),(n?"-":"")+a}function df(i){return!(i>0)||!Number.isFinite(i)?1:10**Math.floor(Math.log10(i))}function uf(i){if(!(i>0))return 1;let t=10**Math.floor(Math.log10(i));for(let e of[1,2,5,10])if(e*t>=i*(1-1e-9))return e*t;return 10*t}function ff(i){if(i===0)return"0";let t=Math.abs(i);return t>=1e5||t<.001?i.toExponential(0).replace("e+","e"):String(Number(i.toPrecision(6)))}function uh(i,t){let e=xt(i,t);return e.dataset.lmSuppressShortcuts="true",e}function pf(i,t){let e=xt("div","tnx-controls");e.setAttribute("role","group"),e.setAttribute("aria-label","Coordinates");let n={};for(let c of"abc"){let l=xt("div","tnx-vertex-row"),h=xt("span","tnx-vertex-name",c.toUpperCase()),u=xt("span","tnx-coords");l.append(h,u),n[c]={name:h,cells:[]},["x","y","z"].forEach((d,f)=>{let m=xt("span","tnx-coord"),y=uh("input","tnx-slider");y.type="range",y.setAttribute("aria-label",`${c.toUpperCase()}.${d} slider`);let g=uh("input","tnx-exact");g.type="text",g.spellcheck=!1,g.autocomplete="off",g.setAttribute("aria-label",`${c.toUpperCase()}.${d}, exact value: type a number such as 0.1, -2 or 1/3 and press Enter`),g.title=`${c.toUpperCase()}.${d}: type a number such as 0.1, -2 or 1/3 and press Enter`,m.append(xt("span","tnx-axis-name",d),y,g),u.appendChild(m),n[c].cells.push({slider:y,box:g});let b=0;y.addEventListener("input",()=>{b||(b=requestAnimationFrame(()=>{b=0;let w=Gs(t.get("step")),p=Ws(Number(y.value),w,t.get("bounds")),_=js(p,w);String((t.get(c)||[])[f]??"")!==_&&(g.value=_,t.edit({[c+d]:_}))}))}),g.addEventListener("input",()=>{g.dataset.dirty="true"});let v=()=>{g.dataset.dirty&&(delete g.dataset.dirty,t.edit({[c+d]:g.value}))};g.addEventListener("change",v),g.addEventListener("keydown",w=>{w.key==="Enter"?v():w.key==="Escape"&&(delete g.dataset.dirty,g.value=String((t.get(c)||[])[f]??""))})}),e.appendChild(l)}let a=xt("div","tnx-settings"),s=xt("label","tnx-decimals","decimals "),r=uh("select");s.appendChild(r),r.addEventListener("change",()=>t.edit({precision:Number(r.value)})),a.appendChild(s),e.appendChild(a),i.appendChild(e);function o(){Wn(e,t.get("show_controls")===!1);let c=Gs(t.get("step")),[l,h]=(t.get("bounds")||[-5,5]).map(Number);for(let m of"abc"){zi(n[m].name,"color",t.color(m.toUpperCase()));let y=(t.get(m)||["","",""]).map(String);n[m].cells.forEach(({slider:g,box:b},v)=>{xe(g,"min",l),xe(g,"max",h),xe(g,"step",c.value);let w=Hi(y[v]);Number.isFinite(w)&&Number(g.value)!==w&&(g.value=String(w)),xe(g,"aria-valuetext",y[v]),!b.dataset.dirty&&b.value!==y[v]&&(b.value=y[v])})}let[u,d]=t.get("precision_range")||[0,15];if(r.options.length!==d-u+1){r.textContent="";for(let m=u;m<=d;m++)r.appendChild(new Option(String(m),String(m)))}let f=String(t.get("precision")??4);r.value!==f&&(r.value=f)}return{update:o,reset(c){for(let l of"abc")n[l].cells.forEach(({box:h},u)=>{c.includes(l+"xyz"[u])&&delete h.dataset.dirty})},dispose(){e.remove()}}}var mf={a:["ax","ay","az"],b:["bx","by","bz"],c:["cx","cy","cz"]},gf=new Set(Object.values(mf).flat()),lx=new Set([...gf,"winding","precision","show_parallelogram","show_unit_normal"]);function bf(i,t,e=()=>performance.now()){let n=0,a={},s=new Map;function r(u){let d=mf[u];if(!d||!d.some(m=>m in a))return u in a?a[u].value:i.get(u);let f=i.get(u)||["","",""];return d.map((m,y)=>m in a?a[m].value:f[y])}function o(u){n+=1;let d=i.get("version")??0;for(let[f,m]of Object.entries(u)){let y=!gf.has(f)||Number.isFinite(Hi(m));lx.has(f)&&y&&(a[f]={value:m,seq:n,base:d})}s.set(n,e()),i.send({edit:u,seq:n,view:t,base:d})}function c(){let u=i.get("last_edit")||{};if(u.view!==t)return!1;for(let[d,f]of Object.entries(a))f.seq<=u.seq&&delete a[d];for(let d of s.keys())d<=u.seq&&s.delete(d);return!0}function l(){let u=i.get("set_at")||{},d=Object.keys(a).filter(f=>(u[f]??0)>a[f].base);for(let f of d)delete a[f];return d}function h(){return s.size?Math.min(...s.values()):null}return{get:r,edit:o,answered:c,overwritten:l,waitingSince:h}}var Im=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),pS=globalThis[Im]||(globalThis[Im]=(vs(),La(_s))),{AmbientLight:Rm,BackSide:wl,BatchedMesh:mI,Box3:an,BufferAttribute:Le,BufferGeometry:$n,ByteType:gI,Color:zn,ConeGeometry:Cm,CylinderGeometry:Nm,DataTexture:bI,DirectionalLight:Pm,DoubleSide:Ui,FloatType:xI,FrontSide:mi,GridHelper:Lm,Group:Al,IntType:yI,Line:_I,Line3:Vn,LineBasicMaterial:Yr,LineLoop:vI,LineSegments:El,MathUtils:MI,Matrix3:SI,Matrix4:qe,Mesh:sn,MeshBasicMaterial:Dm,MeshLambertMaterial:Um,NearestFilter:wI,Object3D:AI,PerspectiveCamera:Om,Plane:Ms,Points:EI,REVISION:Yd,RGBAFormat:TI,RGBAIntegerFormat:II,RGFormat:RI,RGIntegerFormat:CI,Ray:Fm,Raycaster:Tl,RedFormat:NI,RedIntegerFormat:PI,Scene:Bm,ShortType:LI,Sphere:DI,SphereGeometry:km,TOUCH:zm,TorusGeometry:Vm,Triangle:Oi,UnsignedByteType:UI,UnsignedIntType:OI,UnsignedShortType:FI,Vector2:rn,Vector3:et,Vector4:BI,WebGLRenderer:Hm}=pS;var Gm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),mS=globalThis[Gm]||(globalThis[Gm]=(vs(),La(_s))),{OrbitControls:Wm}=mS;var bn=new et(1,.75,.65).normalize(),Jd=40,gS=new et(0,0,1),Jr=44;function bS(){try{let i=document.createElement("canvas").getContext("webgl2");if(!i)return!1;let t=i.getExtension("WEBGL_debug_renderer_info"),e=t?String(i.getParameter(t.UNMASKED_RENDERER_WEBGL)):"";return i.getExtension("WEBGL_lose_context")?.loseContext(),/swiftshader|llvmpipe|softpipe|software/i.test(e)}catch{return!1}}function xS(i,t){let e=t.clone().normalize(),n=new et().crossVectors(i,e);return n.lengthSq()<1e-12&&n.set(1,0,0),n.normalize(),{x:n,y:new et().crossVectors(e,n),z:e}}function yS(i){let t=i.clone().normalize();return Math.abs(t.z)>.999&&t.set(0,-.001,Math.sign(t.z)).normalize(),t}function _S(i){let t=i[0].clone(),e=i[0].clone();for(let n of i)t.min(n),e.max(n);return{center:t.clone().add(e).multiplyScalar(.5),radius:Math.max(e.distanceTo(t)/2,.001)}}function vS(i,t,{width:e,height:n},a=Jr){let s=yS(t),{x:r,y:o,z:c}=xS(gS,s),{center:l,radius:h}=_S(i),u=i.map(_=>_.clone().sub(l).dot(r)),d=i.map(_=>_.clone().sub(l).dot(o)),f=l.clone().addScaledVector(r,(Math.min(...u)+Math.max(...u))/2).addScaledVector(o,(Math.min(...d)+Math.max(...d))/2),m=Math.max(e,1),y=Math.max(n,1),g=Math.tan(Jd/2*Math.PI/180),b=g*m/y,v=Math.max(.4,1-2*a/m),w=Math.max(.4,1-2*a/y),p=1e-6;for(let _ of i){let M=_.clone().sub(f),x=M.dot(c);p=Math.max(p,x+Math.abs(M.dot(r))/(b*v),x+Math.abs(M.dot(o))/(g*w))}return{target:f,distance:Math.max(p*1.02,h*1.2),direction:s}}function MS(i,t){return 2*Math.tan(Jd/2*Math.PI/180)*i/Math.max(t,1)}function ea(i,t,e,n){let a=i.clone().project(t);return{x:(a.x+1)/2*e,y:(1-a.y)/2*n,z:a.z}}function SS(i,t,e,n){let a=i.position.clone().sub(t.target),s=a.length(),r=Math.atan2(a.y,a.x)+e,o=Math.PI/2-.01,c=Math.max(-o,Math.min(o,Math.asin(Math.max(-1,Math.min(1,a.z/s)))+n));a.set(Math.cos(c)*Math.cos(r),Math.cos(c)*Math.sin(r),Math.sin(c)).multiplyScalar(s),i.position.copy(t.target).add(a)}function wS(i,t,e){let n=i.position.clone().sub(t.target).multiplyScalar(e),a=Math.min(Math.max(n.length(),i.near*2),i.far/2);i.position.copy(t.target).addScaledVector(n.normalize(),a)}function AS(i,t,e,n){i.updateMatrixWorld();let a=Jr/2,s=t.map(m=>ea(m,i,e,n)),r=s.map(m=>m.x),o=s.map(m=>m.y),[c,l,h,u]=[Math.min(...r),Math.max(...r),Math.min(...o),Math.max(...o)],d=s.every(m=>m.z<1)&&c>=a&&h>=a&&l<=e-a&&u<=n-a,f=[Math.max(e-2*Jr,1),Math.max(n-2*Jr,1)];return{inside:d,fill:Math.max((l-c)/f[0],(u-h)/f[1])}}function ES(i){let t=new Hm({antialias:!bS()});t.setPixelRatio(Math.min(window.devicePixelRatio||1,2));let e=t.domElement;e.className="tnx-canvas",i.appendChild(e);let n=new Bm,a=new Om(Jd,1,.01,1e3);a.up.set(0,0,1),a.position.copy(bn).multiplyScalar(6);let s=new Wm(a,e);return s.enableDamping=!1,s.zoomToCursor=!1,{renderer:t,canvas:e,scene:n,camera:a,controls:s}}function TS(i,t,e,n){i.aspect=(t+n)/e,n?i.setViewOffset(t+n,e,n,0,t,e):i.clearViewOffset(),i.updateProjectionMatrix()}function Il(i,{onRender:t,margin:e=Jr}){let{renderer:n,canvas:a,scene:s,camera:r,controls:o}=ES(i),c=0,l=1,h=1,u=0,d={points:[new et],direction:bn.clone(),start:bn.clone()},f=!0;function m(){c=0,t(),n.render(s,r)}function y(){c||(c=requestAnimationFrame(m))}function g(){c&&cancelAnimationFrame(c),m()}function b(){return Math.min(u,Math.floor(l/2))}function v(E){let A=Math.max(0,Math.round(E));A!==u&&(u=A,w())}function w(){TS(r,l,h,b()),f&&x(d.direction),y()}function p(){let E=Math.max(1,Math.round(i.clientWidth)),A=Math.max(1,Math.round(i.clientHeight));E===l&&A===h||(l=E,h=A,n.setSize(E,A,!1),w())}let _=new ResizeObserver(p);_.observe(i),o.addEventListener("change",y),o.addEventListener("start",()=>{f=!1});function M(E,A=!0,R=null){R&&d.start.copy(R),d.points=E.map(C=>C.clone()),A==="keep"?x(r.position.clone().sub(o.target)):A&&x(d.start)}function x(E){d.direction.copy(E),f=!0;let{target:A,distance:R,direction:C}=vS(d.points,E,{width:l-b(),height:h},e);r.near=R/200,r.far=R*50,r.updateProjectionMatrix(),o.target.copy(A),r.position.copy(A).addScaledVector(C,R),r.lookAt(A),o.update(),y()}function S(E){E(),f=!1,o.update()}return{renderer:n,canvas:a,scene:s,camera:r,controls:o,requestRender:y,renderNow:g,resize:p,framePoints:M,spread:E=>AS(r,E,l-b(),h),setInset:v,direction:()=>r.position.clone().sub(o.target).normalize(),pixelAt:E=>{let A=o.target.clone().sub(r.position).normalize();return MS(Math.max(E.clone().sub(r.position).dot(A),r.near),h)},reset:()=>x(d.start),turn:(E,A)=>S(()=>SS(r,o,E,A)),zoom:E=>S(()=>wS(r,o,E)),atHome:()=>f,along:E=>x(new et(E==="x"?1:0,E==="y"?-1:0,E==="z"?1:0)),setBackground:E=>{s.background=new zn(E),y()},size:()=>({width:l,height:h}),dispose(){c&&cancelAnimationFrame(c),_.disconnect(),o.dispose(),n.dispose(),n.forceContextLoss?.(),a.remove()}}}var jm=[.25,1],IS=.7,Xm=1e3;function RS(i,t){if(!(i>0&&i<1/0&&t>0&&t<1/0))return 1;let e=Math.log2(i)-Math.log2(t);if(Math.log2(jm[0])<=e&&e<=Math.log2(jm[1]))return 1;let n=Math.floor(Math.log2(IS)-e+.5);return e>0&&(n=Math.min(n,-2)),2**Math.max(-Xm,Math.min(Xm,n))}function Kd(i,t){let e=RS(i,t);return{factor:e,length:i*e}}var CS={1:"½",2:"¼",3:"⅛"},NS={"-":"⁻",0:"⁰",1:"¹",2:"²",3:"³",4:"⁴",5:"⁵",6:"⁶",7:"⁷",8:"⁸",9:"⁹"};function Zd(i,t=!1){let e=t?"N/|N|":"N",n=Math.round(Math.log2(i));if(n===0)return e;let a;return Math.abs(n)>12?a="2"+[...String(n)].map(s=>NS[s]).join(""):n<0?a=CS[-n]||`1/${2**-n}`:a=String(2**n),`${e} × ${a}`}var PS=[20,35,55].flatMap(i=>[...Array(8).keys()].map(t=>{let e=(t*45+37)*Math.PI/180,n=i*Math.PI/180;return new et(Math.cos(n)*Math.cos(e),Math.cos(n)*Math.sin(e),Math.sin(n))})),LS=.25,DS=.7;function $d(i,t){let e=i.clone().normalize();return t.normal?Math.abs(e.dot(t.normal))>=LS:t.line?Math.abs(e.dot(t.line))<=DS:!0}function US(i,t){if(i){let a=Math.abs(bn.dot(i));if(a>=.35&&a<=.8)return bn.clone()}else if(t){if(Math.abs(bn.dot(t))<=.35)return bn.clone()}else return bn.clone();let e=a=>{if(!i)return Math.abs(a.dot(t))<=.35?1-a.dot(bn):3+Math.abs(a.dot(t));let s=a.dot(i);return Math.abs(Math.abs(s)-.65)+(s<0?.05:0)},n=bn.clone();for(let a of PS)e(a)<e(n)-1e-9&&(n=a.clone());return n}function Qd(i){let t=null,e=0;for(let n=0;n<i.length;n++)for(let a=n+1;a<i.length;a++){let s=i[n].distanceTo(i[a]);s>e&&([e,t]=[s,[i[n],i[a]]])}return{ends:t,far:e}}function OS(i){let{ends:t}=Qd(i);return t?t[1].clone().sub(t[0]).normalize():null}function tu(i,t,e,n,a){let s=new et,r=1;if(!n){let l=Kd(i.length()*t,e);r=l.factor,s=i.clone().setLength(l.length)}let o=null,c=1;if(!n&&a){let l=Kd(1/t,e);c=l.factor,o=i.clone().setLength(l.length)}return{nDraw:s,nFactor:r,unitDraw:o,unitFactor:c}}function eu(i,{S:t,offset:e}){return new et(i[0]-e.x,i[1]-e.y,i[2]-e.z).divideScalar(t)}function qm(i,t,e,n=!1){let a=Math.max(...i.flat().map(Math.abs)),s=[[0,1],[0,2],[1,2]].map(([E,A])=>Math.hypot(...i[E].map((R,C)=>R-i[A][C]))),r=Math.max(...s),o=r===0?!0:a<=6*r,l=df(o?a||r||1:r),h=o?new et:new et(...[0,1,2].map(E=>Number(((i[0][E]+i[1][E]+i[2][E])/3).toPrecision(3)))),u=i.map(E=>eu(E,{S:l,offset:h})),d=Math.max(...u.map(E=>Math.max(Math.abs(E.x),Math.abs(E.y),Math.abs(E.z)))),f=uf(Math.max(d,1e-9)/1.5),m=f*(Math.floor(d/f+1e-9)+1.5),y=u.slice(),[g,b,v]=u,w=new et().crossVectors(b.clone().sub(g),v.clone().sub(g));t==="ACB"&&w.negate();let p=Math.max(g.distanceTo(b),g.distanceTo(v),b.distanceTo(v)),_=g.clone().add(b).add(v).divideScalar(3),M=!n&&w.length()>0&&Number.isFinite(w.length());if(M){let{nDraw:E,unitDraw:A}=tu(w,l,p,!1,e);y.push(_.clone().add(E)),A&&y.push(_.clone().add(A))}if(p===0)for(let E of[-1,1])y.push(g.clone().addScalar(E*f/2));let x=M?w.clone().normalize():null,S=M?null:OS(u);return{S:l,offset:h,includeOrigin:o,box:y,L:m,t:f,normal:x,line:S,start:US(x,S)}}function Ym(i,t){return i&&t&&i.S===t.S&&i.includeOrigin===t.includeOrigin&&i.offset.equals(t.offset)}var nu=new et(0,1,0),iu=new et,Ss=class i{constructor(t){this.root=new Al,t.add(this.root),this.owned=[],this.materials={},this.cylinder=this.own(new Nm(1,1,1,18,1).translate(0,.5,0)),this.cone=this.own(new Cm(1,1,24,1).translate(0,.5,0)),this.sphere=this.own(new km(1,28,18)),this.triGeometry=this.own(new $n),this.triGeometry.setAttribute("position",new Le(new Float32Array(9),3)),this.front=this.add(new sn(this.triGeometry,this.material("front",{side:mi,offset:!0}))),this.back=this.add(new sn(this.triGeometry,this.material("back",{side:wl,offset:!0}))),this.paraGeometry=this.own(new $n),this.paraGeometry.setAttribute("position",new Le(new Float32Array(18),3)),this.para=this.add(new sn(this.paraGeometry,this.material("para",{side:Ui,opacity:.28}))),this.paraEdges=[this.stick("paraEdge"),this.stick("paraEdge")],this.edges=[this.stick("edge"),this.stick("edge"),this.stick("edge")],this.ring=[0,1,2].map(()=>this.add(new sn(this.cone,this.material("ring")))),this.vertices={};for(let e of"ABC")this.vertices[e]=this.add(new sn(this.sphere,this.material(e)));this.u=this.arrow("U"),this.v=this.arrow("V"),this.n=this.arrow("N"),this.unit=this.arrow("unit",{opacity:.45}),this.cue=new Al,this.root.add(this.cue),this.cueArc=new sn(void 0,this.material("N")),this.cueHead=new sn(this.cone,this.material("N")),this.cueHead.rotation.z=-Math.PI/2,this.cue.add(this.cueArc,this.cueHead),this.arcs=new Map,this.line=this.stick("line"),this.axes={};for(let e of"xyz")this.axes[e]={arrow:this.arrow(e),ticks:[]};this.grid=null}own(t){return this.owned.push(t),t}add(t){return this.root.add(t),t}material(t,{side:e=mi,opacity:n=1,offset:a=!1}={}){let s=t+":"+e+":"+n+":"+a;if(!this.materials[s]){let r=new Dm({side:e,transparent:n<1,opacity:n,depthWrite:n>=1});a&&Object.assign(r,{polygonOffset:!0,polygonOffsetFactor:1,polygonOffsetUnits:1}),r.userData.role=t,this.materials[s]=r}return this.materials[s]}paint(t){for(let e of Object.values(this.materials))e.color.set(t(e.userData.role))}arrow(t,e={}){let n=new Al,a=new sn(this.cylinder,this.material(t,e)),s=new sn(this.cone,this.material(t,e));return n.add(a,s),this.root.add(n),{group:n,shaft:a,head:s}}stick(t){return this.add(new sn(this.cylinder,this.material(t)))}static placeStick(t,e,n,a){iu.subVectors(n,e);let s=iu.length();t.visible=s>0,s&&(t.position.copy(e),t.quaternion.setFromUnitVectors(nu,iu.divideScalar(s)),t.scale.set(a,s,a))}static placeArrow(t,e,n,a,s=!0){let r=new et().subVectors(n,e),o=r.length();if(t.group.visible=s&&o>0,!t.group.visible)return;let c=Math.min(7*a,.45*o),l=Math.min(2.6*a,c*.5);t.group.position.copy(e),t.group.quaternion.setFromUnitVectors(nu,r.divideScalar(o)),t.shaft.scale.set(a,o-c*.9,a),t.head.position.set(0,o-c,0),t.head.scale.set(l,c,l)}setAxes(t,e,n,a,s){let r=[];for(let o of"xyz"){let c=new et(o==="x"?1:0,o==="y"?1:0,o==="z"?1:0),l=this.axes[o];i.placeArrow(l.arrow,c.clone().multiplyScalar(-t),c.clone().multiplyScalar(t),n,s);let h=s?Math.floor(t/e+1e-9):0;for(;l.ticks.length<2*h;)l.ticks.push(this.add(new sn(this.sphere,this.material(o))));l.ticks.forEach((u,d)=>{let f=d<h?d+1:-(d-h+1);u.visible=d<2*h&&Math.abs(f*e)<t-1e-9,u.position.copy(c).multiplyScalar(f*e),u.scale.setScalar(n*1.9),u.visible&&f>0&&r.push({axis:o,value:f*e,position:u.position.clone()})})}return r}setGrid(t,e,n,a){if(this.grid&&(this.root.remove(this.grid),this.grid.geometry.dispose(),this.grid.material.dispose(),this.grid=null),!a)return;let s=Math.max(2,Math.round(4*t/e));this.grid=new Lm(2*t,s,n.gridMajor,n.grid),this.grid.rotation.x=Math.PI/2,this.grid.material.depthWrite=!1,this.grid.renderOrder=-1,this.root.add(this.grid)}update(t){let{A:e,P:n,Q:a,centroid:s,r}=t,o=this.triGeometry.attributes.position;[e,n,a].forEach((h,u)=>o.setXYZ(u,h.x,h.y,h.z)),o.needsUpdate=!0,this.triGeometry.computeBoundingSphere(),this.front.visible=this.back.visible=!t.degenerate;for(let h of"ABC"){let u=this.vertices[h];u.position.copy(t[h]),u.scale.setScalar(r*(t.degenerate?3.4:2.5))}let c=[e,n,a];for(let h=0;h<3;h++){let u=c[h],d=c[(h+1)%3];i.placeStick(this.edges[h],u,d,r*.45);let f=this.ring[h],m=new et().subVectors(d,u),y=m.length();if(f.visible=!t.degenerate&&y>0,f.visible){let g=Math.min(4.5*r,.22*y),b=new et().addVectors(u,d).multiplyScalar(.5).lerp(s,.22);f.quaternion.setFromUnitVectors(nu,m.divideScalar(y)),f.position.copy(b).addScaledVector(m,-g/2),f.scale.set(g*.45,g,g*.45)}}i.placeArrow(this.u,e,n,r),i.placeArrow(this.v,e,a,r);let l=s.clone().add(t.nDraw);i.placeArrow(this.n,s,l,r*1.15,!t.degenerate),i.placeArrow(this.unit,s,t.unitDraw?s.clone().add(t.unitDraw):s,r*1.9,!t.degenerate&&!!t.unitDraw),this.updateCue(t),this.updateParallelogram(t),this.updateLine(t)}updateCue(t){let e=t.nDraw.clone(),n=e.length();if(t.degenerate||!n){this.cue.visible=!1;return}e.divideScalar(n);let a=new et().subVectors(t.P,t.A),s=new et().subVectors(t.Q,t.A),r=a.clone().addScaledVector(e,-a.dot(e)).normalize(),o=new et().crossVectors(e,r),c=Math.atan2(s.dot(o),s.dot(r));c>0||(c=Math.PI/2),c=Math.max(c,.45*Math.PI);let l=Math.PI/36,h=Math.round(c/l);this.arcs.has(h)||this.arcs.set(h,new Vm(1,.055,8,48,h*l)),this.cueArc.geometry=this.arcs.get(h);let u=h*l;this.cueHead.position.set(Math.cos(u),Math.sin(u),0),this.cueHead.rotation.set(0,0,u),this.cueHead.position.addScaledVector(new et(-Math.sin(u),Math.cos(u),0),-.12),this.cueHead.scale.set(.16,.32,.16);let d=.32*Math.min(a.length(),s.length(),1.2*n)+1e-9,f=new qe().makeBasis(r,o,e);this.cue.quaternion.setFromRotationMatrix(f),this.cue.position.copy(t.centroid).addScaledVector(e,.3*n),this.cue.scale.setScalar(Math.max(d,3*t.r)),this.cue.visible=!0}updateParallelogram(t){let e=t.showParallelogram&&!t.degenerate;if(this.para.visible=e,this.paraEdges.forEach(s=>s.visible=e),!e)return;let n=new et().addVectors(t.P,t.Q).sub(t.A),a=this.paraGeometry.attributes.position;[t.P,n,t.Q,t.P,n,t.Q].forEach((s,r)=>a.setXYZ(r,s.x,s.y,s.z)),a.needsUpdate=!0,this.paraGeometry.computeBoundingSphere(),i.placeStick(this.paraEdges[0],t.P,n,t.r*.45),i.placeStick(this.paraEdges[1],t.Q,n,t.r*.45)}updateLine(t){if(this.line.visible=!1,!t.degenerate)return;let{ends:e,far:n}=Qd([t.A,t.B,t.C]);if(!e||n<t.r)return;let a=new et().subVectors(e[1],e[0]).normalize(),s=Math.max(.35*n,6*t.r),r=e[0].clone().addScaledVector(a,-s),o=e[1].clone().addScaledVector(a,s);i.placeStick(this.line,r,o,t.r*.9)}dispose(){this.setGrid(0,1,null,!1);for(let t of this.arcs.values())t.dispose();for(let t of this.owned)t.dispose();for(let t of Object.values(this.materials))t.dispose();this.root.removeFromParent()}};var FS=22,Km=(i,t)=>i.toLowerCase()+"xyz"[t],Zm={ArrowRight:[0,1],ArrowLeft:[0,-1],ArrowUp:[1,1],ArrowDown:[1,-1],PageUp:[2,1],PageDown:[2,-1]};function Jm(i,t,e){let n=i.canvas.getBoundingClientRect(),a=null,s=FS;for(let r of"ABC"){let o=i.position(r);if(!o)continue;let c=ea(o,i.camera,n.width,n.height),l=Math.hypot(n.left+c.x-t,n.top+c.y-e);l<s&&([a,s]=[r,l])}return a}function BS(i,t,e,n,a){let s={};return i.strings.forEach((r,o)=>{let c=r,l=t.getComponent(o);if(Math.abs(l)>=e.value/2){let h=Ws(i.start[o]+l,e,n);dh(i.start[o],h,e)||(c=js(h,e))}c!==r&&i.moved.add(o),i.moved.has(o)&&c!==a[o]&&(s[Km(i.name,o)]=c)}),s}function kS(i,t,e){let[n,a]=Zm[e],s=i.values(t)[n],r=i.grid(),o=Hi(s);Number.isFinite(o)||(o=(i.position(t)?.getComponent(n)??0)*i.scale());let c=Ws(o+a*r.value,r,i.bounds());if(dh(o,c,r))return null;let l=js(c,r);return l!==s?{[Km(t,n)]:l}:null}function $m(i){let t=new Tl,e=new rn,n=new Ms,a=null,s=null,r=0;function o(p,_){let M=i.canvas.getBoundingClientRect();return e.set((p-M.left)/M.width*2-1,-((_-M.top)/M.height)*2+1),t.setFromCamera(e,i.camera),t.ray.intersectPlane(n,new et)}function c(p,_){let M=i.position(p);if(!M)return!1;let x=i.camera.getWorldDirection(new et);n.setFromNormalAndCoplanarPoint(x,M);let S=o(_.clientX,_.clientY);if(!S)return!1;let E=i.values(p).slice();return a={name:p,pointerId:_.pointerId,hit:S,strings:E,moved:new Set,start:E.map((A,R)=>{let C=Hi(A);return Number.isFinite(C)?C:M.getComponent(R)*i.scale()})},i.container.setPointerCapture(_.pointerId),i.container.classList.add("tnx-dragging"),i.dragging(!0,p),!0}function l(){if(r=0,!a||!s)return;let p=o(s.clientX,s.clientY);if(s=null,!p)return;let _=p.sub(a.hit).multiplyScalar(i.scale()),M=BS(a,_,i.grid(),i.bounds(),i.values(a.name));Object.keys(M).length&&i.write(M)}function h(p){if(a||p.button>0||p.pointerType==="touch"&&i.touchActive&&!i.touchActive())return;let _=p.target.closest?.("[data-vertex]"),M=_?_.dataset.vertex:p.target===i.canvas?Jm(i,p.clientX,p.clientY):null;M&&c(M,p)&&(p.preventDefault(),p.stopPropagation(),_&&_.focus({preventScroll:!0}))}function u(p){if(!a){p.target===i.canvas&&p.buttons===0&&(i.canvas.style.cursor=Jm(i,p.clientX,p.clientY)?"grab":"");return}p.pointerId===a.pointerId&&(p.preventDefault(),s={clientX:p.clientX,clientY:p.clientY},r||(r=requestAnimationFrame(l)))}function d(p){let _=a.name;a=null,s=null,i.container.classList.remove("tnx-dragging"),i.container.hasPointerCapture?.(p)&&i.container.releasePointerCapture(p),i.dragging(!1,_)}function f(p){!a||p.pointerId!==a.pointerId||(s&&(cancelAnimationFrame(r),r=0,p.type!=="pointercancel"&&l()),d(p.pointerId))}function m(){a&&(r&&cancelAnimationFrame(r),r=0,d(a.pointerId))}function y(p){let _=p.target.closest?.("[data-vertex]");if(!_||!(p.key in Zm)||p.altKey||p.ctrlKey||p.metaKey)return;p.preventDefault();let M=kS(i,_.dataset.vertex,p.key);M&&i.write(M)}let g=i.container,b=Fe(g,{pointerdown:h},{capture:!0}),v=Fe(g,{pointermove:u,pointerup:f,pointercancel:f,keydown:y}),w=()=>{r&&cancelAnimationFrame(r),b(),v()};return w.cancel=m,w}function zS(i,t){if(i.dataset.text===t)return;i.dataset.text=t,i.textContent="";let n=String(t).startsWith("(")?i.appendChild(xt("span","tnx-vector")):i,a=String(t).split(/(?<=,) | (?=[+=−-] )/);a.forEach((s,r)=>{n.appendChild(xt("span","tnx-part",s)),r<a.length-1&&n.appendChild(document.createTextNode(" "))})}function Qm(i){let t=xt("section","tnx-readout");t.setAttribute("aria-label","Readout");let e=xt("table","tnx-table"),n=xt("tbody");e.appendChild(n);let a=xt("p","tnx-status"),s=xt("p","tnx-summary");s.setAttribute("aria-live","polite"),s.setAttribute("role","status"),t.append(e,a,s),i.appendChild(t);let r=0;function o(l){let h=Array.isArray(l?.readout)?l.readout:[];for(;n.rows.length>h.length;)n.deleteRow(-1);h.forEach((d,f)=>{let m=n.rows[f]||n.insertRow();if(m.cells.length===0){let y=xt("th");y.scope="row",m.append(y,xt("td","tnx-value"))}xe(m,"data-key",d.key),Be(m.cells[0],d.label),zS(m.cells[1],l.ok===!1?"—":d.value)}),Be(a,(l?.ok===!1?l.error:l?.status)||""),xe(a,"data-state",l?.ok===!1?"error":l?.degenerate?"degenerate":"ok"),clearTimeout(r);let u=l?.ok===!1&&l.error||"";r=setTimeout(()=>{s.textContent!==u&&(s.textContent=u)},350)}function c(l){xe(t,"aria-busy",l?"true":"false"),e.classList.toggle("tnx-waiting",!!l),l&&(Be(a,l),xe(a,"data-state","waiting"))}return{update:o,waiting:c,show(l){Wn(t,!l)},dispose(){clearTimeout(r),t.remove()}}}var VS="Drag empty space to turn the view, scroll or pinch to zoom; x, y, z look along an axis. Drag A, B or C to move a point, or Tab to it and press the arrow keys (x, y) or Page Up/Page Down (z). On a touch screen, tap the view first, then drag.";function tg(i){let t=xt("div","tn-view tnx-root");t.dataset.lmSuppressShortcuts="true";let e=xt("div","tnx-main"),n=xt("div","tnx-side"),a=po("tnx-toolbar","3D view"),s=xt("div","tnx-stage tn-stage");s.tabIndex=-1,s.dataset.lmSuppressShortcuts="true";let r=xt("p","tnx-message");r.hidden=!0,r.setAttribute("role","status");let o=xt("p","tnx-legend");o.hidden=!0;let c=xt("p","tnx-error");c.hidden=!0,c.setAttribute("role","alert");let l=xt("p","tnx-hint",VS);e.append(a,s,r,c,o),t.append(e,n),i.appendChild(t);let h=Qm(n);return n.appendChild(l),{root:t,main:e,side:n,toolbarEl:a,stageEl:s,message:r,error:c,legend:o,hint:l,readout:h}}function eg(i,{model:t,controls:e,keys:n}){let{root:a,main:s,stageEl:r,hint:o,readout:c}=i;r.remove(),o.remove(),s.appendChild(xt("p","tnx-nogl","This browser cannot draw the 3D view (WebGL is not available). The readout still follows the values."));let l=()=>{c.show(!0),c.update(t.get("state")),e.update()};l();for(let h of n)t.on("change:"+h,l);return()=>{for(let h of n)t.off("change:"+h,l);a.remove()}}function ng(i){let t=0,e=null;function n(a,s){let r=a&&a.printed;if(!r||r.seq!==t||!e)return;if(r.error){Be(e,r.error);return}let o=s&&s[0];if(!o)return;let c=o instanceof DataView?new Uint8Array(o.buffer,o.byteOffset,o.byteLength):new Uint8Array(o);mo(new Blob([c],{type:"model/stl"}),r.name,e.ownerDocument||document),Be(e,r.done||"")}return i.on("msg:custom",n),{request(a,s){t+=1,e=s,Be(e,""),i.send({print:{marks:a,seq:t}})},stop:()=>i.off("msg:custom",n)}}function ig(i,t){let e=i&&i.ok!==!1&&Array.isArray(i.readout)?i.readout.find(n=>n.key===t):null;return e?e.value:null}function ag(i,t){let{get:e,readout:n,message:a,error:s}=i,r=!!e("show_readout")||i.root.classList.contains("tn-fullscreen");n.show(r),i.side.classList.toggle("tnx-no-readout",!r),r&&n.update(t);let o=t.ok===!1?t.error||t.status:t.degenerate?t.status:"";Wn(a,!o),Be(a,o||""),xe(a,"data-state",t.ok===!1?"error":"degenerate");let c=i.model.get("message")||"";Wn(s,!c),Be(s,c),i.controls.update();for(let l of"ABC"){let h=e(l.toLowerCase())||[];xe(i.vertexEls[l],"aria-label",`Point ${l} at (${h.join(", ")}). Arrow keys move x and y, Page Up and Page Down move z.`)}}function sg(i,t){let e=i.get("state"),n=ig(e,"magnitude"),a=ig(e,"area"),s=t&&n!==null&&a!==null;Wn(i.legend,!s),s&&Be(i.legend,`Parallelogram on U and V: area |N| = ${n}. Triangle: area |N|/2 = ${a}.`)}var Kr=2,Zr={width:84,height:44},rg="http://www.w3.org/2000/svg",HS={enter:"M4 9V4h5M15 4h5v5M20 15v5h-5M9 20H4v-5",exit:"M9 4v5H4M20 9h-5V4M15 20v-5h5M4 15h5v5",save:"M12 4v11M7 10l5 5 5-5M5 20h14"};function og(i,t,e){i.setAttribute("aria-label",e),i.title=e,i.querySelector("path").setAttribute("d",HS[t])}function cg(i,t,e){let n=xt("button","tn-present-button");n.type="button";let a=document.createElementNS(rg,"svg");return a.setAttribute("viewBox","0 0 24 24"),a.setAttribute("aria-hidden","true"),a.setAttribute("focusable","false"),a.appendChild(document.createElementNS(rg,"path")),n.appendChild(a),og(n,i,t),n.addEventListener("click",e),n}function GS(i){let t=i&&i.tagName||"";return t==="INPUT"||t==="TEXTAREA"||t==="SELECT"||!!(i&&i.isContentEditable)}function WS(i,t){let e=i.ownerDocument||document,n=!1,a=cg("enter","Full screen",()=>c());a.setAttribute("aria-keyshortcuts","f");let s=()=>n||e.fullscreenElement===i;function r(){let u=s();i.classList.toggle("tn-fullscreen",u),og(a,u?"exit":"enter",u?"Exit full screen":"Full screen"),t(u)}function o(u){n=u,r()}function c(){if(n)return o(!1);if(e.fullscreenElement===i)return void e.exitFullscreen();if(!i.requestFullscreen)return o(!0);i.requestFullscreen().catch(()=>o(!0))}let l=Fe(e,{fullscreenchange:r,keydown:u=>{n&&u.key==="Escape"&&o(!1)}}),h=Fe(i,{keydown:u=>{u.key!=="f"||u.altKey||u.ctrlKey||u.metaKey||GS(u.target)||(u.preventDefault(),u.stopPropagation(),c())}});return{button:a,toggle:c,dispose(){e.fullscreenElement===i&&e.exitFullscreen(),l(),h()}}}function jS(i,t,e){let n=t.getBoundingClientRect();if(!n.width||!n.height)return;let a=getComputedStyle(t),s=n.left-e.left,r=n.top-e.top,o=Math.min(parseFloat(a.borderTopLeftRadius)||0,n.width/2,n.height/2);i.beginPath(),i.roundRect(s,r,n.width,n.height,o),a.backgroundColor&&a.backgroundColor!=="rgba(0, 0, 0, 0)"&&(i.fillStyle=a.backgroundColor,i.fill());let c=parseFloat(a.borderTopWidth)||0;c&&(i.lineWidth=c,i.strokeStyle=a.borderTopColor,i.stroke()),i.fillStyle=a.color,i.font=`${a.fontWeight} ${a.fontSize} ${a.fontFamily}`,i.textAlign="center",i.textBaseline="middle",i.fillText(t.textContent,s+n.width/2,r+n.height/2)}function au(i){let{renderer:t,canvas:e}=i,{width:n,height:a}=i.size(),s=t.getPixelRatio(),r=xt("canvas");r.width=n*Kr,r.height=a*Kr;let o=r.getContext("2d");t.setPixelRatio(Kr),t.setSize(n,a,!1);try{i.renderNow(),o.drawImage(e,0,0,r.width,r.height)}finally{t.setPixelRatio(s),t.setSize(n,a,!1),i.renderNow()}o.scale(Kr,Kr);let c=e.parentElement.getBoundingClientRect(),l=[...e.parentElement.querySelectorAll(".tnx-label")].filter(h=>!h.hidden);for(let h of l.sort((u,d)=>(Number(getComputedStyle(u).zIndex)||0)-(Number(getComputedStyle(d).zIndex)||0)))jS(o,h,c);return new Promise(h=>r.toBlob(h,"image/png"))}function Rl({root:i,stage:t,filename:e,onFullscreen:n=()=>{}}){let a=xt("div","tn-present");a.setAttribute("role","group"),a.setAttribute("aria-label","Picture");let s=WS(i,n);return a.append(s.button,cg("save","Save picture",async()=>mo(await au(t),e))),t.canvas.parentElement.appendChild(a),()=>{s.dispose(),a.remove()}}function lg(i,t,e,n,a){return i+e>a.width-Zr.width&&t-n<Zr.height&&a.height>Zr.height+2*n+4?Zr.height+n+2:t}var Cl=class{constructor(t,e=null){this.beforeLayout=e,this.el=document.createElement("div"),this.el.className="tnx-labels",t.appendChild(this.el),this.items=new Map}label(t,e,n){let a=this.items.get(t);if(!a){let s=document.createElement("div");s.className="tnx-label tnx-"+e,this.el.appendChild(s),a={el:s,kind:e,anchor:null,away:null,offset:0,visible:!0,text:null},this.items.set(t,a)}return n!==void 0&&a.text!==n&&(a.el.textContent=n,a.text=n,a.half=null),a}place(t,e,{away:n=null,offset:a=0,angle:s=null,visible:r=!0}={}){let o=this.items.get(t);o&&(o.anchor=e?e.clone():null,o.away=n?n.clone():null,o.offset=a,o.angle=s,o.visible=r&&!!e)}hide(t){for(let[e,n]of this.items)e.startsWith(t)&&(n.visible=!1)}layout(t,e){this.beforeLayout&&this.beforeLayout();let n=[];for(let a of this.items.values()){let s=a.visible&&a.anchor?ea(a.anchor,t,e.width,e.height):null;if(!s||s.z>1||s.z<-1){Wn(a.el,!0);continue}let r=s.x,o=s.y;if(a.offset){let c=0,l=0;if(a.away){let u=ea(a.away,t,e.width,e.height);c=s.x-u.x,l=s.y-u.y}let h=Math.hypot(c,l);h<8&&a.angle!==null?(c=Math.cos(a.angle),l=-Math.sin(a.angle)):h<1e-6?(c=0,l=-1):(c/=h,l/=h),r+=c*a.offset,o+=l*a.offset}if(a.kind==="vertex"){for(let c of n)Math.hypot(c.x-r,c.y-o)<30&&a.angle!==null&&(r=s.x+Math.cos(a.angle)*a.offset*1.4,o=s.y-Math.sin(a.angle)*a.offset*1.4);r=Math.min(Math.max(r,20),e.width-20),o=Math.min(Math.max(o,20),e.height-20),o=lg(r,o,20,20,e),n.push({x:r,y:o})}if(Wn(a.el,!1),a.kind==="arrow"){(!a.half||!a.half.w)&&(a.half={w:a.el.offsetWidth/2,h:a.el.offsetHeight/2});let{w:c,h:l}=a.half;e.width>2*c+4&&(r=Math.min(Math.max(r,c+2),e.width-c-2)),e.height>2*l+4&&(o=Math.min(Math.max(o,l+2),e.height-l-2)),o=lg(r,o,c,l,e)}a.el.style.transform=`translate(${r.toFixed(1)}px, ${o.toFixed(1)}px) translate(-50%, -50%)`}}dispose(){this.el.remove(),this.items.clear()}};function ws(i=document){let t=i.body;return t?t.dataset.jpThemeLight!==void 0?t.dataset.jpThemeLight==="false":(t.dataset.mdColorScheme??i.documentElement.dataset.mdColorScheme)==="slate":!1}function Nl(i,t=document){let e=ws(t),n=new MutationObserver(()=>{let s=ws(t);s!==e&&(e=s,i(e))}),a=["data-md-color-scheme","data-jp-theme-light","data-jp-theme-name"];return t.body&&n.observe(t.body,{attributes:!0,attributeFilter:a}),n.observe(t.documentElement,{attributes:!0,attributeFilter:a}),()=>n.disconnect()}function $r(i,t,e){let n=i&&i[t];return n?e?n.dark:n.light:gi(e).text}function gi(i){return i?{background:"#1b1d24",text:"#f2f2f2",grid:"#4a4f5c",gridMajor:"#6b7180",line:"#ffd166"}:{background:"#ffffff",text:"#1a1a1a",grid:"#d4d7de",gridMajor:"#9aa0ab",line:"#b3261e"}}var XS={A:225*Math.PI/180,B:-30*Math.PI/180,C:90*Math.PI/180};function hg(i,t){let e=new Cl(i,()=>$S(t)),n={};for(let a of"ABC"){let r=e.label("v:"+a,"vertex",a).el;r.dataset.vertex=a,r.tabIndex=0,r.dataset.lmSuppressShortcuts="true",r.setAttribute("role","button"),r.setAttribute("aria-roledescription","movable point"),r.setAttribute("aria-keyshortcuts","ArrowLeft ArrowRight ArrowUp ArrowDown PageUp PageDown"),n[a]=r}for(let[a,s]of[["U","U"],["V","V"],["N","N"],["unit","N/|N|"]])e.label("arrow:"+a,"arrow",s);for(let a of"xyz")e.label("axis:"+a,"axis",a);return{labels:e,vertexEls:n}}function su(i){let{get:t}=i,e=[t("a"),t("b"),t("c")].map(hf);if(e.every(Boolean))return e;let n=t("state");if(n&&n.ok&&n.points){let a=["A","B","C"].map(s=>n.points[s]);if(a.every(s=>Array.isArray(s)&&s.every(Number.isFinite)))return a}return i.lastGood}function ru(i,t,e=i.get("winding")){let n=i.get("state")||{};return qm(t,e,i.get("show_unit_normal"),!!n.degenerate)}var ou=2.4,qS=6,YS=8,JS=2,KS=2.3,ZS=.4;function $S(i){let{stage:t,drawing:e,frame:n,last:a}=i;if(!n||!a)return;let s=ou*t.pixelAt(t.controls.target);Math.abs(s/a.r-1)<.01||(a.r=s,e.update(a),e.setAxes(n.L,n.t,s*.5,i.colors,n.includeOrigin));let r=a.degenerate?YS:qS;for(let o of"ABC"){let c=e.vertices[o];c.scale.setScalar(r*t.pixelAt(c.position))}n.includeOrigin&&QS(i)}function QS(i){let{stage:t,drawing:e,frame:n}=i,a=t.controls.target.clone().sub(t.camera.position).normalize(),s=o=>o.clone().sub(t.camera.position).dot(a),r=ZS*s(t.controls.target);for(let o of"xyz"){let c=new et(o==="x"?1:0,o==="y"?1:0,o==="z"?1:0),l=s(new et),h=c.dot(a),[u,d]=[-n.L,n.L];if(Math.abs(h)>1e-12){let b=(r-l)/h;h>0?u=Math.max(u,b):d=Math.min(d,b)}else l<r&&(d=u);let{arrow:f,ticks:m}=e.axes[o],y=d>u,g=JS*t.pixelAt(c.clone().multiplyScalar(h>0?u:d));Ss.placeArrow(f,c.clone().multiplyScalar(u),c.clone().multiplyScalar(d),g,y),f.head.visible=!(y&&d<n.L);for(let b of m)b.visible&&b.scale.setScalar(s(b.position)<r?0:KS*t.pixelAt(b.position))}}function Ra(i,t,e){let{stage:n,drawing:a,labels:s,colors:r}=i;if(i.frame=t,e===!1)n.framePoints(t.box,!1);else{let l=e==="keep"&&$d(n.direction(),t);n.framePoints(t.box,l?"keep":!0,t.start)}let o=ou*n.pixelAt(n.controls.target),c=a.setAxes(t.L,t.t,o*.5,r,t.includeOrigin);a.setGrid(t.L,t.t,gi(i.dark),t.includeOrigin),s.hide("tick:"),c.forEach((l,h)=>{let u=`tick:${l.axis}:${h}`;s.label(u,"tick",ff(l.value*t.S)),s.place(u,l.position,{offset:16,angle:l.axis==="z"?0:-Math.PI/2})});for(let l of"xyz"){let h=new et(l==="x"?t.L:0,l==="y"?t.L:0,l==="z"?t.L:0);s.place("axis:"+l,h,{away:new et,offset:18,visible:t.includeOrigin}),zi(s.items.get("axis:"+l).el,"color",r(l))}}function dg(i,t,e){let{stage:n}=i;if(!i.dragging){let a=ru(i,t,e),s=i.frame,r=i.drawnWinding&&i.drawnWinding!==e;if(!s)Ra(i,a,!0);else if(i.hostMoved||r)Ra(i,a,n.atHome()?!0:"keep");else if(!Ym(s,a))Ra(i,a,"keep");else{let{inside:o,fill:c}=n.spread(a.box);!o||c<.35||!$d(n.direction(),a)?Ra(i,a,"keep"):Ra(i,a,!1)}i.drawnWinding=e}i.hostMoved=!1}function tw(i,t,e,n){let{labels:a,vertexEls:s,colors:r}=i,{A:o,P:c,Q:l,centroid:h,nDraw:u,unitDraw:d,degenerate:f}=t;for(let y of"ABC")a.place("v:"+y,t[y],{away:h,offset:30,angle:XS[y]}),zi(s[y],"color",r(y));a.place("arrow:U",o.clone().lerp(c,.5),{away:h,offset:20,visible:e.length()>0}),a.place("arrow:V",o.clone().lerp(l,.5),{away:h,offset:20,visible:n.length()>0});let m=h.clone().add(u);a.place("arrow:N",m,{away:h,offset:20,angle:0,visible:!f}),a.place("arrow:unit",d?h.clone().add(d):null,{away:h,offset:20,angle:Math.PI,visible:!!d});for(let y of["U","V","N","unit"])zi(a.items.get("arrow:"+y).el,"color",r(y))}function ug(i,t,e,n){let{get:a,labels:s,frame:r}=i,{S:o}=r,[c,l,h]=t.map(A=>eu(A,r)),[u,d]=n==="ABC"?[l,h]:[h,l],f=c.clone().add(l).add(h).divideScalar(3),m=u.clone().sub(c),y=d.clone().sub(c),g=new et().crossVectors(m,y),b=g.length(),v=!!e.degenerate||!(b>0)||!Number.isFinite(b),w=Math.max(m.length(),y.length(),u.distanceTo(d),1e-9),{nDraw:p,nFactor:_,unitDraw:M,unitFactor:x}=tu(g,o,w,v,a("show_unit_normal"));s.label("arrow:N","arrow",Zd(_)),s.label("arrow:unit","arrow",Zd(x,!0)),i.scales={N:_,unit:M?x:null};let S=ou*i.stage.pixelAt(i.stage.controls.target),E={A:c,B:l,C:h,P:u,Q:d,centroid:f,nDraw:p,unitDraw:M,degenerate:v,showParallelogram:!!a("show_parallelogram"),r:S};return i.drawing.update(E),i.last=E,i.display={A:c,B:l,C:h},i.heads={U:u,V:d,N:v?null:f.clone().add(p),unit:M?f.clone().add(M):null},tw(i,E,m,y),E.showParallelogram&&!v}function fg(i){let{display:t,heads:e,frame:n,stage:a,get:s}=i;if(!t||!n)return null;let{width:r,height:o}=a.size();a.camera.updateMatrixWorld();let c={};for(let[f,m]of Object.entries({...t,...e})){if(!m)continue;let y=ea(m,a.camera,r,o);c[f]=[y.x,y.y]}let l=a.camera.position.distanceTo(a.controls.target),h=t.A.clone().add(t.B).add(t.C).divideScalar(3),u=f=>f?f.clone().sub(h).multiplyScalar(n.S).toArray():null,d={N:u(e.N),unit:u(e.unit),scales:{...i.scales}};return{width:r,height:o,distance:l,points:c,drawn:d,values:["a","b","c"].map(f=>(s(f)||[]).map(String))}}var pg=".tnx-root{--tnx-chip: rgba(255,255,255,.92);display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}.tnx-root.tn-dark{--tnx-chip: rgba(27,29,36,.9)}.tnx-main{flex:1 1 400px;min-width:min(360px,100%);max-width:100%}.tnx-side{flex:1 1 360px;min-width:0;max-width:100%;container-type:inline-size}.tnx-side.tnx-no-readout{flex-basis:100%}.tnx-toolbar{display:flex;flex-wrap:wrap;gap:4px;margin:0 0 6px;container-type:inline-size}.tnx-toolbar button,.tnx-print button{font:inherit;font-size:14px;line-height:1.2;padding:5px 7px;min-height:32px;min-width:32px;flex:0 0 auto;white-space:nowrap;border-radius:6px;cursor:pointer;border:1px solid var(--tn-muted);background:var(--tn-bg);color:var(--tn-fg)}.tnx-short{display:none}@container (max-width: 470px){.tnx-toolbar .tnx-long{display:none}.tnx-toolbar .tnx-short{display:inline}.tnx-toolbar button{padding:5px 6px}}.tnx-toolbar button[aria-pressed=true]{background:var(--tn-fg);color:var(--tn-bg)}.tnx-toolbar button:focus-visible,.tnx-print button:focus-visible,.tnx-vertex:focus-visible{outline:3px solid #0072B2;outline-offset:2px}.tnx-stage{position:relative;width:100%;height:var(--tnx-height,clamp(170px, calc(100vh - 310px) ,370px));max-height:80vh;min-height:170px;overflow:hidden;border:1px solid var(--tn-muted);border-radius:0;background:var(--tn-bg);touch-action:pan-y;user-select:none;-webkit-user-select:none}.tnx-canvas{display:block;width:100%!important;height:100%!important;outline:none}.tnx-labels{position:absolute;inset:0;pointer-events:none;overflow:hidden}.tnx-label{position:absolute;left:0;top:0;white-space:nowrap;font-weight:700;font-size:19px;line-height:1;will-change:transform}.tnx-arrow,.tnx-axis,.tnx-tick{padding:2px 4px;border-radius:4px;background:var(--tnx-chip)}.tnx-tick{font-weight:400;font-size:14px;color:var(--tn-fg)}.tnx-vertex{pointer-events:auto;cursor:grab;touch-action:pan-y;min-width:34px;min-height:34px;display:flex;align-items:center;justify-content:center;font-size:19px;border-radius:50%;border:3px solid currentColor;background:var(--tnx-chip)}.tnx-dragging .tnx-vertex,.tnx-dragging .tnx-canvas{cursor:grabbing}.tnx-touch-active .tnx-stage,.tnx-touch-active .tnx-vertex{touch-action:none}.tnx-touch-active .tnx-stage,.tnx-stage:focus-visible{outline:3px solid #0072B2;outline-offset:-3px}.tnx-message,.tnx-error{margin:6px 0 0;padding:4px 10px;border-radius:6px;font-size:15px;border-left:5px solid #e69f00;color:var(--tn-fg)}.tnx-error,.tnx-message[data-state=error],.tnx-status[data-state=error]{border-left-color:#d55e00;font-weight:700}.tnx-tick{z-index:1}.tnx-axis{z-index:2}.tnx-arrow{z-index:3}.tnx-vertex{z-index:5}.tnx-legend{margin:6px 0 0;padding:0 10px;font-size:15px;color:var(--tn-fg)}.tnx-hint{margin:6px 0 0;font-size:14px;color:var(--tn-muted)}.tnx-readout{min-width:0;font-size:15px}.tnx-root .tnx-readout table{border-collapse:collapse;width:100%}.tnx-root .tnx-readout th{text-align:left;line-height:1.25;padding:1px 10px 1px 0;white-space:nowrap;font-weight:700;vertical-align:top}.tnx-root .tnx-readout td{padding:1px 0;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;line-height:1.25}.tnx-root .tnx-vector,.tnx-root .tnx-part{white-space:nowrap}@container (max-width: 340px){.tnx-readout tr,.tnx-readout th,.tnx-root .tnx-readout td{display:block}.tnx-root .tnx-readout .tnx-vector{white-space:normal}.tnx-root .tnx-readout td{padding:0 0 4px .8em}}.tnx-status{margin:6px 0 0;padding:4px 8px;border-left:4px solid #009e73}.tnx-status[data-state=degenerate]{border-left-color:#e69f00}.tnx-status[data-state=waiting]{border-left-color:currentColor;font-style:italic}.tnx-table.tnx-waiting .tnx-value{opacity:.55}.tnx-summary{position:absolute;width:1px;height:1px;margin:-1px;overflow:hidden;clip:rect(0 0 0 0);white-space:nowrap}.tnx-root.tn-fullscreen{display:block;overflow:hidden;font-size:18px}.tn-fullscreen .tnx-main{display:flex;flex-direction:column;width:100%;height:100%}.tn-fullscreen .tnx-side{position:absolute;top:96px;right:18px;z-index:10;width:min(420px,40vw);box-sizing:border-box;max-height:calc(100vh - 90px);overflow:auto;padding:8px 12px;border-radius:6px;background:var(--tnx-chip)}.tn-fullscreen .tnx-readout{font-size:18px}.tn-fullscreen .tnx-readout tr,.tn-fullscreen .tnx-readout th,.tn-fullscreen.tnx-root .tnx-readout td{display:block}.tn-fullscreen.tnx-root .tnx-readout td{padding:0 0 4px .8em}.tn-fullscreen.tnx-root .tnx-readout .tnx-vector{white-space:normal}.tn-fullscreen .tnx-hint,.tn-fullscreen .tnx-message,.tn-fullscreen .tnx-controls{display:none}.tnx-nogl{padding:12px;border:1px solid var(--tn-muted);border-radius:6px}.tnx-controls{flex:1 1 100%;display:flex;flex-direction:column;gap:4px;font-size:15px}.tnx-vertex-row{display:flex;align-items:baseline;gap:4px 12px}.tnx-vertex-name{flex:none;font-weight:700;font-size:16px;width:1.2em}.tnx-coords{display:flex;flex-wrap:wrap;align-items:center;gap:4px 12px;min-width:0}.tnx-coord{display:inline-flex;align-items:center;gap:4px}.tnx-axis-name{display:inline-block;width:.8em;color:var(--tn-muted)}.tnx-slider{width:7em;margin:0;accent-color:#0072B2}.tnx-exact,.tnx-decimals select{font:inherit;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;width:4.6em;padding:2px 4px;border:1px solid var(--tn-muted);border-radius:4px;background:var(--tn-bg);color:var(--tn-fg)}.tnx-decimals select{width:auto}.tnx-exact:focus-visible,.tnx-slider:focus-visible,.tnx-decimals select:focus-visible{outline:3px solid #0072B2;outline-offset:1px}.tnx-print{display:flex;flex-wrap:wrap;gap:4px;margin:6px 0 0}.tnx-print-status{flex-basis:100%;font-size:13px;margin:0}";var mg={ABC:"A→B→C",ACB:"A→C→B"};function na(i,t,e){let n=xt("button","tnx-button",i);return n.type="button",t&&(n.setAttribute("aria-label",t),n.title=t),n.addEventListener("click",e),n}function gg(i,{get:t,edit:e,stage:n,reset:a,onFullscreen:s}){let r=na("",null,()=>e({winding:t("winding")==="ACB"?"ABC":"ACB"})),o=(m,y)=>na(y,null,()=>e({[m]:!t(m)})),c=o("show_parallelogram","");c.append(xt("span","tnx-long","Parallelogram"),xt("span","tnx-short","▱")),c.setAttribute("aria-label","Parallelogram");let l=o("show_unit_normal","N/|N|");l.setAttribute("aria-label","Unit normal N/|N|"),l.title="Show the unit normal N/|N|",c.title="Show the parallelogram on U and V (area |N|)";let h=na("","Reset view",a);h.append(xt("span","tnx-long","Reset view"),xt("span","tnx-short","Reset")),h.title="Reset view: frame the triangle and its arrows again",i.append(h,na("x","View along the x axis",()=>n.along("x")),na("y","View along the y axis",()=>n.along("y")),na("z","View along the z axis",()=>n.along("z")),r,c,l);let u=i.closest(".tn-view")||i.parentElement,d=Rl({root:u,stage:n,filename:"triangle.png",onFullscreen:s});function f(){let m=t("winding")==="ACB"?"ACB":"ABC";Be(r,`⇄ ${mg[m]}`),xe(r,"aria-label",`Flip the order of the vertices, now ${mg[m]}`),xe(r,"title",r.getAttribute("aria-label")),xe(c,"aria-pressed",!!t("show_parallelogram")),xe(l,"aria-pressed",!!t("show_unit_normal"))}return{update:f,dispose:d}}function bg(i,t){let e=xt("div","tnx-print");e.setAttribute("role","group"),e.setAttribute("aria-label","3D printing");let n=xt("p","tnx-print-status");n.setAttribute("role","status");let a=na("Download for 3D printing",null,()=>t("letters",n));a.title="An STL file of the triangle as a plate, N as an arrow, U and V as ridges, A, B, C in letters";let s=na("With braille marks","Download for 3D printing with braille marks",()=>t("braille",n));s.title="The same model with A, B and C marked in braille",e.append(a,s,n),i.append(e)}function nw(i){let t={};for(let e of["a","b","c"])t[e]=(i(e)||[]).map(String);return t.winding=i("winding")==="ACB"?"ACB":"ABC",t.show_parallelogram=!!i("show_parallelogram"),t.show_unit_normal=!!i("show_unit_normal"),t}function iw(i,t){let{camera:e}=i.stage;e.updateMatrixWorld();let{width:n,height:a}=i.stage.size();return JSON.stringify([t,n,a,i.dark,i.get("palette"),e.matrixWorld.elements,e.projectionMatrix.elements])}function xg(i,{settleMs:t,take:e=au}){let{model:n,stage:a,root:s}=i,r=0,o=!1,c=!1,l="",h=!1;function u(){if(r=0,h||i.dragging||o||!n.get("send_pictures"))return;let{width:m,height:y}=a.size();if(!a.canvas.isConnected||m<2||y<2||!i.frame)return;let g=nw(i.get),b=iw(i,g);if(b===l)return;l=b,c=!0;let v;try{v=e(a)}finally{c=!1}v.then(w=>w?w.arrayBuffer():null).then(w=>{h||!w||(n.send({picture:g},void 0,[w]),s.tnxPicture={values:g,width:m,height:y})})}function d(){c||h||(clearTimeout(r),r=setTimeout(u,t))}let f=Fe(a.controls,{start:()=>{o=!0},end:()=>{o=!1,d()}});return{rendered:d,stop(){h=!0,clearTimeout(r),f()}}}var aw=10,sw=600;function Pl({root:i,stageEl:t,controls:e,canvas:n,activeClass:a}){let s=!1;function r(f){s=f,i.classList.toggle(a,f),e.touches.ONE=f?zm.ROTATE:null,n.style.touchAction=f?"none":"pan-y"}r(!1);let o=null,c=f=>{o=f.pointerType==="touch"?{x:f.clientX,y:f.clientY,t:performance.now(),id:f.pointerId}:null},l=f=>{if(!o||f.pointerId!==o.id)return;let m=Math.hypot(f.clientX-o.x,f.clientY-o.y)<aw&&performance.now()-o.t<sw;o=null,m&&!s&&r(!0)},h=f=>{s&&!i.contains(f.target)&&r(!1)},u=i.ownerDocument||document,d=[Fe(t,{pointerdown:c},{capture:!0}),Fe(t,{pointerup:l}),Fe(u,{pointerdown:h},{capture:!0})];return{active:()=>s,dispose(){for(let f of d)f()}}}var yg=["a","b","c","winding","precision","step","bounds","show_parallelogram","show_unit_normal","show_readout","show_controls","precision_range","palette","state","message"];function rw(i,t){let e=gi(i.dark);switch(t){case"edge":case"paraEdge":case"ring":case"unit":return e.text;case"para":return $r(i.get("palette"),"N",i.dark);case"line":return e.line;default:return $r(i.get("palette"),t,i.dark)}}function Qr(i){let t=su(i),e=i.get("state")||{},n=i.get("winding")==="ACB"?"ACB":"ABC";i.toolbar.update(),ag(i,e),i.readout.waiting(i.waiting&&i.model.get("waiting")||""),i.drawing.root.visible=!!t,t&&(i.lastGood=t,dg(i,t,n),sg(i,ug(i,t,e,n))),i.stage.requestRender()}function cu(i){let{frame:t,drawing:e,labels:n}=i;if(i.root.classList.toggle("tn-dark",i.dark),i.stage.setBackground(gi(i.dark).background),e.paint(i.colors),t){e.setGrid(t.L,t.t,gi(i.dark),t.includeOrigin);for(let a of"xyz")zi(n.items.get("axis:"+a).el,"color",i.colors(a))}Qr(i)}var ow=400;function cw(i,t,e){let n=0;function a(){clearTimeout(n);let s=t.waitingSince(),r=s===null?1/0:s+ow-performance.now(),o=r<=0;o!==i.waiting&&(i.waiting=o,e()),!o&&r!==1/0&&(n=setTimeout(a,r))}return a.stop=()=>clearTimeout(n),a}function lw(i,t,e){let{model:n}=i,a=!1,s=()=>{a||(a=!0,queueMicrotask(()=>{a&&(a=!1,Qr(i))}))};i.flush=()=>{a=!1,Qr(i),i.stage.renderNow()};let r={};for(let l of yg)r[l]=l==="palette"?()=>cu(i):s;let o=cw(i,t,s);i.checkWaiting=o,r.last_edit=()=>{t.answered()&&s(),o()};let c=n.get("version")??0;r.version=()=>{let l=n.get("set_at")||{},h=Object.keys(l).filter(u=>l[u]>c);c=n.get("version")??0,t.overwritten(),i.dragged&&h.some(u=>u[0]===i.dragged.toLowerCase())&&e.cancel(),i.controls.reset(h),i.hostMoved=!0,s()};for(let[l,h]of Object.entries(r))n.on("change:"+l,h);return()=>{o.stop();for(let[l,h]of Object.entries(r))n.off("change:"+l,h)}}var hw=0;function dw({model:i,el:t}){Vi(t.ownerDocument||document,"trinormal-explorer-style",pg);let e=`v${++hw}-${Math.random().toString(36).slice(2,8)}`,n=tg(t),a=bf(i,e),{get:s}=a,r=y=>{a.edit(y),o.checkWaiting?.()},o={...n,model:i,get:s,dark:ws(),frame:null,dragging:!1,dragged:null,waiting:!1,lastGood:null,hostMoved:!1,display:null,heads:{},scales:{}};o.colors=y=>rw(o,y),o.controls=pf(n.root,{get:s,edit:r,color:o.colors});try{o.stage=Il(n.stageEl,{onRender:()=>{o.labels.layout(o.stage.camera,o.stage.size()),o.pictures?.rendered()}})}catch{return eg(n,{model:i,controls:o.controls,keys:yg})}let{stage:c}=o;Object.assign(o,hg(n.stageEl,o)),o.drawing=new Ss(c.scene);let l=ng(i);o.toolbar=gg(n.toolbarEl,{get:s,edit:r,stage:c,reset:()=>{o.frame&&Ra(o,ru(o,o.lastGood||su(o)),!0),c.reset()},onFullscreen(y){Qr(o),o.stage.setInset(y?n.side.offsetWidth+24:0)}}),bg(n.side,l.request);let h=Pl({root:n.root,stageEl:n.stageEl,controls:c.controls,canvas:c.canvas,activeClass:"tnx-touch-active"}),u=$m({touchActive:h.active,container:n.stageEl,canvas:c.canvas,camera:c.camera,scale:()=>o.frame?.S??1,grid:()=>Gs(s("step")),bounds:()=>s("bounds"),values:y=>(s(y.toLowerCase())||["","",""]).map(String),position:y=>o.display?o.display[y]:null,write(y){r(y),o.flush()},dragging(y,g){o.dragging=y,o.dragged=y?g:null,y||Qr(o)}}),d=lw(o,a,u),f=Nl(y=>{o.dark=y,cu(o)});n.root.tnxProject=()=>fg(o),c.resize(),cu(o);let m=lf(o);return o.pictures=xg(o,{settleMs:hh}),()=>{o.pictures.stop(),m(),d(),o.toolbar.dispose(),l.stop(),h.dispose(),f(),u(),o.labels.dispose(),o.drawing.dispose(),c.dispose(),n.readout.dispose(),o.controls.dispose(),n.root.remove()}}var lu={render:dw};var uw=1500;function fw(i,t,e){let n=i.length/3,a=new Float32Array(18*n),s=0,r=new et,o=new et,c=new et;for(let l=0;l<n;l++){if(r.set(t[3*l],t[3*l+1],t[3*l+2]),!(r.lengthSq()>0))continue;r.normalize();let h=i[3*l],u=i[3*l+1],d=i[3*l+2],f=h+r.x*e,m=u+r.y*e,y=d+r.z*e;c.set(Math.abs(r.z)<.9?0:1,0,Math.abs(r.z)<.9?1:0),o.crossVectors(r,c).normalize().multiplyScalar(.22*e);let g=f-r.x*.35*e,b=m-r.y*.35*e,v=y-r.z*.35*e;a.set([h,u,d,f,m,y,f,m,y,g+o.x,b+o.y,v+o.z,f,m,y,g-o.x,b-o.y,v-o.z],s),s+=18}return a.subarray(0,s)}function _g(i,t){let e=Math.max(1,Math.ceil(i/t)),n=new Int32Array(Math.ceil(i/e));for(let a=0,s=0;a<i;a+=e,s++)n[s]=a;return n}function pw(i,t){let e=_g(t.length/3,2e3),n=[];for(let a of e){let s=t[3*a],r=t[3*a+1];n.push(Math.hypot(i[3*s]-i[3*r],i[3*s+1]-i[3*r+1],i[3*s+2]-i[3*r+2]))}return n.sort((a,s)=>a-s),n.length?n[n.length>>1]:.1}function mw(i,t){let e=i.arrow_faces||new Int32Array(0),n=i.arrow_normals||new Float32Array(0);if(!e.length||n.length!==3*e.length)return null;let a=new Float32Array(3*e.length);for(let s=0;s<e.length;s++)for(let r=0;r<3;r++){let o=i.faces[3*e[s]+r];for(let c=0;c<3;c++)a[3*s+c]+=t[3*o+c]/3}return{starts:a,dirs:n}}function gw(i,t){let e=i.vertex_normals;if(!e||e.length!==t.length)return null;let n=_g(t.length/3,uw),a=new Float32Array(3*n.length),s=new Float32Array(3*n.length);return n.forEach((r,o)=>{for(let c=0;c<3;c++)a[3*o+c]=t[3*r+c],s[3*o+c]=e[3*r+c]}),{starts:a,dirs:s}}function vg(i){let t={face:new Yr,vertex:new Yr},e={};function n(r,o){let c=new $n;c.setAttribute("position",new Le(r,3));let l=new El(c,o);return l.renderOrder=2,i.add(l),l}function a(r,o){let c=.5*pw(o,r.faces);for(let[l,h]of[["face",mw(r,o)],["vertex",gw(r,o)]])h&&(e[l]=n(fw(h.starts,h.dirs,c),t[l]))}function s(){for(let r of Object.values(e))i.remove(r),r.geometry.dispose();e={}}return{draw:a,has:r=>!!e[r],count:r=>e[r]?e[r].geometry.getAttribute("position").count/6:0,show(r,o){e[r]&&(e[r].visible=o)},setColors(r,o){t.face.color=new zn(r),t.vertex.color=new zn(o)},clear:s,dispose(){s();for(let r of Object.values(t))r.dispose()}}}function ia(i,t){if(!t)return new i(0);if(ArrayBuffer.isView(t)&&!(t instanceof DataView))return t;let{buffer:e,byteOffset:n,byteLength:a}=t;return n%i.BYTES_PER_ELEMENT===0?new i(e,n,a/i.BYTES_PER_ELEMENT):new i(e.slice(n,n+a))}function Mg(i){let t=i.get("mesh");if(t)return t;let e=i.get("positions");return!e||!e.byteLength?null:{positions:ia(Float64Array,e),faces:ia(Uint32Array,i.get("faces")),flipped:ia(Int32Array,i.get("flipped")),boundary:ia(Int32Array,i.get("boundary")),non_manifold:ia(Int32Array,i.get("non_manifold")),arrow_faces:ia(Int32Array,i.get("arrow_faces")),arrow_normals:ia(Float32Array,i.get("arrow_normals")),vertex_normals:ia(Float32Array,i.get("vertex_normals"))}}function bw(i){let t=[1/0,1/0,1/0],e=[-1/0,-1/0,-1/0];for(let s=0;s<i.length;s+=3)for(let r=0;r<3;r++){let o=i[s+r];o<t[r]&&(t[r]=o),o>e[r]&&(e[r]=o)}if(!(t[0]<=e[0]))return{offset:[0,0,0],scale:1};let n=t.map((s,r)=>(s+e[r])/2),a=Math.hypot(e[0]-t[0],e[1]-t[1],e[2]-t[2])/2;return{offset:n,scale:a>0&&Number.isFinite(a)?2/a:1}}function Sg(i){let{offset:t,scale:e}=bw(i),n=new Float32Array(i.length);for(let a=0;a<n.length;a++)n[a]=(i[a]-t[a%3])*e;return{pos:n,offset:t,scale:e}}var As=8,Ll=(i,t,e=t+"s")=>`${i} ${i===1?t:e}`,xw=i=>i.length<2?i.join(""):i.slice(0,-1).join(", ")+" and "+i[i.length-1];function yw(i){let t=i.slice(0,As).map(String);return i.length>As&&t.push(`${i.length-As} more`),xw(t)}function wg(i,t=!0){let e=[i.closed?"closed":"open (it has a hole)"];return i.outward===!1&&e.push("facing inward"),t&&i.faces_to_flip&&e.push(`${Ll(i.faces_to_flip,"face")} to flip`),e.join(", ")}function _w({about:i,faces:t,flipped:e,picked:n,selection:a}){if(!t)return"No model is shown.";let s=i&&i.name?i.name:"The model",r=i&&Array.isArray(i.pieces)?i.pieces:null,o=[`${s}: ${Ll(t,"face")}${r?` in ${Ll(r.length,"piece")}`:""}.`];if(r&&r.length>1){let h=r.slice(0,As).map((u,d)=>`piece ${d+1}, ${Ll(u.faces,"face")}: ${wg(u)}`);r.length>As&&h.push(`${r.length-As} more`),o.push(`Its pieces: ${h.join("; ")}.`)}else r&&r.length===1&&o.push(`The piece is ${wg(r[0],!1)}.`);let c=e?Array.from(e):[];o.push(c.length?`${c.length===1?"Face":"Faces"} to flip (outlined): ${yw(c)}.`:"No face needs flipping.");let l=a&&a.face===n&&Array.isArray(a.rows)?a.rows:[];return l.length&&o.push(`Picked: ${a.title}. ${l.map(([h,u])=>`${h}: ${u}`).join("; ")}.`),o.join(" ")}function Ag(i){Vi(i.ownerDocument||document,"trinormal-access-style",xo);let t=xt("p","tnm-describe");return t.id=`tnm-describe-${Math.random().toString(36).slice(2,10)}`,t.setAttribute("role","status"),t.setAttribute("aria-live","polite"),i.after(t),i.setAttribute("aria-describedby",t.id),{update:e=>Be(t,_w(e)),dispose:()=>t.remove()}}var Eg=28,vw=4096;function Tg(i){let t=i.length/3,e=[];for(let r of[-1,0,1])for(let o of[-1,0,1])for(let c of[-1,0,1])(r||o||c)&&e.push([r,o,c]);let n=e.map(()=>[-1/0,0]);for(let r=0;r<t;r++){let o=i[3*r],c=i[3*r+1],l=i[3*r+2];for(let h=0;h<e.length;h++){let u=e[h],d=u[0]*o+u[1]*c+u[2]*l;d>n[h][0]&&(n[h]=[d,r])}}let a=new Set(n.map(r=>r[1])),s=Math.max(1,Math.ceil(t/vw));for(let r=0;r<t;r+=s)a.add(r);return[...a].map(r=>new et(i[3*r],i[3*r+1],i[3*r+2]))}function Ig(i,t,e){let n=e.flipped.length?e.flipped:e.boundary.length?e.boundary:e.non_manifold;if(!n.length)return bn.clone();let a=new et;for(let s=0;s<n.length;s++){let r=t[n[s]];a.x+=i[3*r],a.y+=i[3*r+1],a.z+=i[3*r+2]}return a.divideScalar(n.length),a.length()>1e-6?a.normalize().multiplyScalar(3).add(bn).normalize():bn.clone()}var Es=(function(){var i="b9H79Tebbbe;veC9Geueu9Geub9Gbb9Gsuuuuuuuuuuuu99uueu9Gvuuuuub9Gruuuuuuub9Gouuuuuue999Gvuuuuueu9Gzuuuuuuuuuuu99uuuub9Gquuuuuuu99uueu9GPuuuuuuuuuuu99uueu9Gquuuuuuuu99ueu9Gruuuuuu99eu9Gwuuuuuu99ueu9Giuuue999GDuuuuuuuuueu9Gkuuuuuuuu99uub9Gluuuueu9Gluuuub9Giuuueui3EdilvorlwDiqkrxmPszdHObAAbeAlve9Weiiviebeoweuecj:Gdkr:Sdmo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bbz9TW79O9V9Wt9F79P9T9W29P9M95bw8E9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9OcttV9P9I91tW7bD8A9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9O9v9W9K9HtWbqQ9TW79O9V9Wt9F79P9T9W29P9M959t29V9W9W95bkX9TW79O9V9Wt9F79P9T9W29P9M959qV919UWbmQ9TW79O9V9Wt9F79P9T9W29P9M959q9V9P9Ut7bPX9TW79O9V9Wt9F79P9T9W29P9M959t9J9H2WbsP9TW79O9V9Wt9FVW9TW79Obza9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94SWt9J9O9sW9T9H9WbA59TW79O9V9Wt9F9NW9UWV9HtW9q9V79Pt9P9V9U9sW9T9H9WbCl79IV9RbXDwebcekdKYq:p:1dElbzOk:Q:tekYue99iuQ99eui99Due99xue9:w998Jjjjjbcj;sb9Rgs8Kjjjjbcbhzasc:Cefcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkdnamcdGTmbalcrfci4cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egecdtfaHBdbasaecefBd;8ecbhlcbhednadTmbabheadhOinaHaeydbci4fcb86bbaeclfheaOcufgOmbkcbhlabheadhOinaHaeydbgAci4fgCaCRbbgCceaAcrGgAtV86bbaCcu7aA4ceGalfhlaeclfheaOcufgOmbkcualcdtalcFFFFi0Ehekaecbyd;y:L:cjbHjjjjbbhzasc:Cefasyd;8egecdtfazBdbasaecefBd;8ealcd4alfhOcehHinaHgecethHaeaO6mbkcbhXcuaecdtgOaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egAcdtfaHBdbasaAcefBd;8eaHcFeaOz:xjjjbhQdnadTmbaecufhLcbhKindndnaQabaKcdtfgYydbgAc:v;t;h;Ev2aLGgOcdtfgCydbgHcuSmbceheinazaHcdtfydbaASmdaOaefhHaecefheaQaHaLGgOcdtfgCydbgHcu9hmbkkazaXcdtfaABdbaCaXBdbaXhHaXcefhXkaYaHBdbaKcefgKad9hmbkkaQcbyd;C:L:cjbH:bjjjbbasasyd;8ecufBd;8ekcbh8AcualcefgecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhKasc:Cefasyd;8egecdtfaKBdbasaKBdNeasaecefBd;8ecuadcitadcFFFFe0Ecbyd;y:L:cjbHjjjjbbhEasc:Cefasyd;8egecdtfaEBdbasaEBd:yeasaecefBd;8eascNefabadalcbz:cjjjbcualcdtgealcFFFFi0Eg3cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egOcdtfaHBdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhXasc:Cefasyd;8egOcdtfaXBdbasaOcefBd;8eaHaXaialavazasc:Cefz:djjjbalcbyd;y:L:cjbHjjjjbbh5asc:Cefasyd;8egOcdtfa5BdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhOasc:Cefasyd;8egAcdtfaOBdbasaAcefBd;8ea3cbyd;y:L:cjbHjjjjbbhAasc:Cefasyd;8egCcdtfaABdbasaCcefBd;8eaOcFeaez:xjjjbh8EaAcFeaez:xjjjbh8FdnalTmbindnaKa8AgAcefg8AcdtfydbgCaKaAcdtgefydbgOSmbaCaO9RhYaEaOcitfhaa8Faefhha8EaefhLcbhCindndnaaaCcitfydbgQaA9hmbaLaABdbahaABdbxekdnaKaQcdtggfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheinaeydbaASmdaecwfheaOcufgOmbkka8FagfgeaAaQaeydbcuSEBdbaLaQaAaLydbcuSEBdbkaCcefgCaY9hmbkka8Aal9hmbkaHhOaXhAa8EhQa8FhCcbheindndnaeaOydbgL9hmbdnaeaAydbgL9hmbaQydbhLdnaCydbgYcu9hmbaLcu9hmba5aefcb86bbxikdnaYcuSmbaLcuSmbaeaYSmbaHaYcdtfydbaHaLcdtfydb9hmba5aefcd86bbxika5aefhadnaeaYSmbaeaLSmbaace86bbxikaacv86bbxdkdnaeaXaLcdtgYfydb9hmbdnaCydbgacuSmbaeaaSmbaQydbggcuSmbaeagSmba8FaYfydbghcuSmbahaLSmba8EaYfydbgYcuSmbaYaLSmbaHaacdtfydbgLaHaYcdtfydb9hmbaLaHagcdtfydbgYSmbaYaHahcdtfydb9hmba5aefcd86bbxika5aefcv86bbxdka5aefcv86bbxeka5aefa5aLfRbb86bbkaOclfhOaAclfhAaQclfhQaCclfhCalaecefge9hmbkdnamcaGTmbcbh8Jindndna5a8Jfg8KRbbg8Lc9:fPlbeebekdndndnaHa8Jcdtfydbgea8J9hmbcbhYcbh8MaqTmednazTmbcbh8Ma8JheinaqazaecdtgefydbfRbbce4a8MVceGh8MaXaefydbgea8J9hmbxikkcbh8Ma8JheinaqaefRbbce4a8MVceGh8MaXaecdtfydbgea8J9hmbxdkka5aefRbbhexeka8JheindnaKaecdtg8AfgeclfydbgOaeydbgeSmbaOae9RhgaEaecitfhhaHa8AfhacbhLinahaLcitfydbgQhednindnaKaecdtgCfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheaaydbhAdninaHaeydbcdtfydbaASmeaecwfheaOcufgOTmdxbkkcbhexdkaXaCfydbgeaQ9hmbkcehekaYaeVhYaLcefgLag9hmbkkaXa8Afydbgea8J9hmbka8LclciaYceGEa8MEheka8Kae86bbka8Jcefg8Jal9hmbkkdnaqTmbdndnazTmbazheaHhOalhAindnaqaeydbfRbbceGTmba5aOydbfcv86bbkaeclfheaOclfhOaAcufgAmbxdkkaqheaHhOalhAindnaeRbbceGTmba5aOydbfcv86bbkaecefheaOclfhOaAcufgAmbkkaHhealhAa5hOindna5aeydbfRbbcv9hmbaOcv86bbkaeclfheaOcefhOaAcufgAmbkkamceGTmba5healhOindndnaeRbbcufPlbeebekaecv86bbkaecefheaOcufgOmbkkcbh8Ncualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh8Kasc:Cefasyd;8egecdtfa8KBdbasaecefBd;8eascbBd:qeas9cb83i1ea8Kaialavazasc1efz:ejjjbhydndnaDmbcbh8PcbhaxekcbhaawhecbhOindnaeIdbJbbbb9ETmbasaacdtfaOBdbaacefhakaeclfheaDaOcefgO9hmbkcuaaal2gecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbh8Pasc:Cefasyd;8egecdtfa8PBdbasaecefBd;8ealTmbdnaambcbhaxekarcd4hgdnazTmbaacdthhcbhLa8PhYinaoazaLcdtfydbag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbxdkkaacdthhcbhLa8PhYinaoaLag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbkkcualc8S2gOalc;D;O;f8U0EgCcbyd;y:L:cjbHjjjjbbheasc:Cefasyd;8egAcdtfaeBdbasaAcefBd;8eaecbaOz:xjjjbhIcbh8RcbhgdnaaTmbcbh8NaCcbyd;y:L:cjbHjjjjbbhgasc:Cefasyd;8egecdtfagBdbasaecefBd;8eagcbaOz:xjjjb8Acuaaal2gecltgOaecFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Rasc:Cefasyd;8egecdtfa8RBdbasaecefBd;8ea8RcbaOz:xjjjb8AamcjjjjdGTmbcualcltgealcFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Nasc:Cefasyd;8egOcdtfa8NBdbasaOcefBd;8ea8Ncbaez:xjjjb8AkdnadTmbcbhQabhOina8KaOclfydbgLcx2fgeIdba8KaOydbgYcx2fgAIdbg8S:tgRa8KaOcwfydbghcx2fgCIdlaAIdlg8U:tg8VNaeIdla8U:tg8WaCIdba8S:tg8XN:tg8Ya8YNa8WaCIdwaAIdwg8Z:tg80NaeIdwa8Z:tg8Wa8VN:tg81a81Na8Wa8XNaRa80N:tg80a80NMMg8V:rhBa8Yh8Xa80h8Wa81hRdna8VJbbbb9EgATmba8YaB:vh8Xa80aB:vh8Wa81aB:vhRkaIaHaYcdtfydbgCc8S2fgeaRaB:rg8VaRNNg83aeIdbMUdbaea8Wa8Va8WNgUNg85aeIdlMUdlaea8Xa8Va8XNg86Ng87aeIdwMUdwaeaRaUNgUaeIdxMUdxaea86aRNg88aeIdzMUdzaea8Wa86Ng89aeIdCMUdCaeaRa8Va8Xa8ZNaRa8SNa8Ua8WNMM:mg8:Ng86NgRaeIdKMUdKaea8Wa86Ng8WaeId3MUd3aea8Xa86Ng8XaeIdaMUdaaea86a8:Ng86aeId8KMUd8Kaea8VaeIdyMUdyaIaHaLcdtfydbgLc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdyaIaHahcdtfydbgYc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdydna8NTmbdnaATmba8YaB:vh8Ya80aB:vh80a81aB:vh81ka8NaCcltfgeaBJbbbZNgRa80Ng8VaeIdlMUdlaeaRa8YNg8WaeIdwMUdwaeaRa81Ng8XaeIdbMUdbaeaRa8S:ma81Na8Ua80N:ta8Za8YN:tNgRaeIdxMUdxa8NaLcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxa8NaYcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxkaOcxfhOaQcifgQad6mbkkdnalTmbJq;x8J88J;n;m;m89J:v:;;w8ZamczGEamc;abGEh80cbhOaHhCazhQaIhea8KhAindnaOaCydb9hmbaOhLdnazTmbaQydbhLka80hRdnaqTmbJbbjZa80aqaLfRbbclGEhRkaecxfgLaLIdbJbbbbMUdbaeczfgLaLIdbJbbbbMUdbaecCfgLaLIdbJbbbbMUdbaeaRaecyfgLIdbg8YNgRaeIdbMUdbaeclfgYaRaYIdbMUdbaecwfgYaRaYIdbMUdbaecKfgYaYIdbaAIdbg8WaRN:tUdbaAcwfIdbh8Vaec3fgYaYIdbaRaAclfIdbg8XN:tUdbaecafgYaYIdbaRa8VN:tUdbaec8KfgYIdbh81aLa8YaRMUdbaYa81aRa8Va8VNa8Wa8WNa8Xa8XNMMNMUdbkaCclfhCaQclfhQaec8SfheaAcxfhAalaOcefgO9hmbkkdnadTmbcbh8AabhLinaba8AcdtfhYcbheindna5aLaefydbgCfRbbgOTmba5aYaec:G:G:cjbfydbcdtfydbgQfRbbcFeGgATmbdnaOclSghmbaOci6mbaAclSmbaAcd0mekdnaOcd0mba8EaCcdtfydbaQ9hmekdnaAcd0mba8FaQcdtfydbaC9hmekdndnahmbaAcl9hmekaOciSmeaAciSmekJbbbZJbbbZJbbacaAcdSEaOcdSEhUdna8KaYaec:K:G:cjbfydbcdtfydbcx2fgOIdwa8KaCcx2fgAIdwg86:tg8Sa8KaQcx2fghIdwa86:tg8Xa8XNahIdbaAIdbg8U:tg80a80NahIdlaAIdlg8Z:tg8Va8VNMMg81Na8Xa8Sa8XNaOIdba8U:tg83a80Na8VaOIdla8Z:tg85NMMg8WN:tg8Ya8YNa83a81Na80a8WN:tgRaRNa85a81Na8Va8WN:tg8Wa8WNMMgBJbbbb9ETmba8YaB:rgB:vh8Ya8WaB:vh8WaRaB:vhRkaUa81:rNgBa8Ya86NaRa8UNa8Za8WNMM:mg81Ng87a81Nh88a80a85Na8Va83N:tg81a81Na8Va8SNa8Xa85N:tg8Va8VNa8Xa83Na80a8SN:tg8Xa8XNMMg83:rh80a8Ya87Nh85a8Wa87Nh89aRa87Nh87a8WaBa8YNg8SNh8:a8SaRNhZaRaBa8WNgnNhca8Ya8SNh8Ya8WanNh8WaRaBaRNNh8Sdna83Jbbbb9ETmba81a80:vh81a8Xa80:vh8Xa8Va80:vh8VkaIaHaCcdtfydbc8S2fgOaOIdba8Sa8VaUa80:rNgRa8VNNMg80MUdbaOa8Wa8XaRa8XNg8SNMg83aOIdlMUdlaOa8Ya81aRa81Ng8WNMg8YaOIdwMUdwaOaca8Va8SNMg8SaOIdxMUdxaOaZa8Wa8VNMgUaOIdzMUdzaOa8:a8Xa8WNMg8WaOIdCMUdCaOa87a8VaRa81a86Na8Va8UNa8Za8XNMMg86:mNgRNMg8VaOIdKMUdKaOa89a8XaRNMg8XaOId3MUd3aOa85a81aRNMg81aOIdaMUdaaOa88a86aRN:tgRaOId8KMUd8KaOaBaOIdyMUdyaIaHaQcdtfydbc8S2fgOa80aOIdbMUdbaOa83aOIdlMUdlaOa8YaOIdwMUdwaOa8SaOIdxMUdxaOaUaOIdzMUdzaOa8WaOIdCMUdCaOa8VaOIdKMUdKaOa8XaOId3MUd3aOa81aOIdaMUdaaOaRaOId8KMUd8KaOaBaOIdyMUdykaeclfgecx9hmbkaLcxfhLa8Acifg8Aad6mbkkdnamcjeGTmbalTmbcbh9cindnaKa9cgecdtgOfydbghaKaecefg9ccdtfydbg8M9pmba8Kaecx2fhDaIaHaOfydbgCc8S2fh8AindnaHaEahcitfgeydbgLcdtfydbg8JaC0mbaeydlh8LcuhAaLheindnaKaecdtgYfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheindnaHaeydbcdtfydbaC9hmbaAcu9hhQaLhAaQmbaeclfydbhAkaecwfheaOcufgOmbkkaXaYfydbgeaL9hmbkaAaLSmbaAcuSmba8KaLcx2fgeIdbaDIdbg81:tgRa8Ka8Lcx2fgOIdlaDIdlg80:tg8XNaeIdla80:tg8VaOIdba81:tg8YN:tg86a8KaAcx2fgAIdba81:tg8Za8VNaAIdla80:tg83aRN:tg8SNa8VaOIdwaDIdwgB:tg8UNaeIdwaB:tg8Wa8XN:tg85a83a8WNaAIdwaB:tg87a8VN:tgUNa8Wa8YNaRa8UN:tg88a87aRNa8Za8WN:tg89NMMa86a86Na85a85Na88a88NMM:rJ:A:z9z:;Na8Sa8SNaUaUNa89a89NMM:rN9Gmbdna8Ua8Wa8WNaRaRNa8Va8VNMMg8SNa8Wa8Ua8WNa8YaRNa8Va8XNMMg86N:tg8Ua8UNa8Ya8SNaRa86N:tg8Ya8YNa8Xa8SNa8Va86N:tg86a86NMMg8XJbbbb9ETmba8Ua8X:rg8X:vh8Ua86a8X:vh86a8Ya8X:vh8Yka8S:rg8Xa8UaBNa8Ya81Na80a86NMM:mgUNg85aUNhUa8Ua85Nh88a86a85Nh89a8Ya85Nh8:a86a8Xa8UNg85NhZa85a8YNhna8Ya8Xa86NgcNhJa8Ua85Nh8Ua86acNh86a8Ya8Xa8YNNh85dna87a8SNa8Wa87a8WNa8ZaRNa8Va83NMMg8YN:tg8Wa8WNa8Za8SNaRa8YN:tgRaRNa83a8SNa8Va8YN:tg8Va8VNMMg8YJbbbb9ETmba8Wa8Y:rg8Y:vh8Wa8Va8Y:vh8VaRa8Y:vhRka8Aa8AIdba85aRa8XaRNNMg8SMUdba8Aa86a8Va8Xa8VNg8ZNMg86a8AIdlMUdla8Aa8Ua8Wa8Xa8WNg8YNMg8Ua8AIdwMUdwa8AaJaRa8ZNMg8Za8AIdxMUdxa8Aana8YaRNMg83a8AIdzMUdza8AaZa8Va8YNMg85a8AIdCMUdCa8Aa8:aRa8Xa8WaBNaRa81Na80a8VNMMg81:mNg8YNMgRa8AIdKMUdKa8Aa89a8Va8YNMg8Va8AId3MUd3a8Aa88a8Wa8YNMg8Wa8AIdaMUdaa8AaUa81a8YN:tg8Ya8AId8KMUd8Ka8Aa8Xa8XMg8Xa8AIdyMUdyaIa8Jc8S2fgea8SaeIdbMUdbaea86aeIdlMUdlaea8UaeIdwMUdwaea8ZaeIdxMUdxaea83aeIdzMUdzaea85aeIdCMUdCaeaRaeIdKMUdKaea8VaeId3MUd3aea8WaeIdaMUdaaea8YaeId8KMUd8Kaea8XaeIdyMUdykahcefgha8M9hmbkka9cal9hmbkkdnadTmbaaTmbcbhYinJbbbbh80a8KabaYcdtfgeclfydbgLcx2fgOIdwa8Kaeydbghcx2fgAIdwg8Z:tg8Va8VNaOIdbaAIdbg83:tg8Wa8WNaOIdlaAIdlg85:tg8Xa8XNMMg8Sa8Kaecwfydbg8Acx2fgeIdwa8Z:tg8YNa8Va8YNa8WaeIdba83:tg81Na8XaeIdla85:tgBNMMgRa8VN:tJbbbbJbbjZa8Sa8Ya8YNa81a81NaBaBNMMg8UNaRaRN:tg86:va86Jbbbb9BEg86Nh88a8Ua8VNaRa8YN:ta86Nh89a8SaBNaRa8XN:ta86Nh8:a8Ua8XNaRaBN:ta86NhZa8Sa81NaRa8WN:ta86Nhna8Ua8WNaRa81N:ta86Nhca8WaBNa8Xa81N:tgRaRNa8Xa8YNa8VaBN:tgRaRNa8Va81Na8Wa8YN:tgRaRNMM:rJbbbZNhRa8Pahaa2g8JcdtfhOa8Pa8Aaa2g8McdtfhAa8PaLaa2gDcdtfhCa8Z:mhJa85:mh9ea83:mhTascjdfheaahQJbbbbhBJbbbbh86Jbbbbh8SJbbbbh8UJbbbbh8ZJbbbbh83Jbbbbh85Jbbbbh87JbbbbhUinaecwfaRa89aCIdbaOIdbg8Y:tg8XNa88aAIdba8Y:tg81NMg8VNUdbaeclfaRaZa8XNa8:a81NMg8WNUdbaeaRaca8XNana81NMg8XNUdbaecxfaRaJa8VNa9ea8WNa8YaTa8XNMMMg8YNUdbaRa8Va8WNNa8ZMh8ZaRa8Va8XNNa8UMh8UaRa8Wa8XNNa8SMh8SaRa8Ya8YNNaUMhUaRa8Va8YNNa87Mh87aRa8Wa8YNNa85Mh85aRa8Xa8YNNa83Mh83aRa8Va8VNNa86Mh86aRa8Wa8WNNaBMhBaRa8Xa8XNNa80Mh80aOclfhOaCclfhCaAclfhAaeczfheaQcufgQmbkagahc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyagaLc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyaga8Ac8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdya8Ra8JcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8RaDcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8Ra8McltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbkaYcifgYad6mbkkcbhAdndnamcwGgSmbJbbbbh86cbh9hcbh9icbh6xekcbh9ha3cbyd;y:L:cjbHjjjjbbh6asc:Cefasyd;8egecdtfa6BdbasaecefBd;8ecua6alabadaHz:fjjjbgCcltaCcjjjjiGEcbyd;y:L:cjbHjjjjbbh9iasc:Cefasyd;8egecdtfa9iBdbasaecefBd;8ea9iaCa6a8Kalz:gjjjbJFFuuh86aCTmba9iheaChOinaeIdbgRa86a86aR9EEh86aeclfheaOcufgOmbkaCh9hkdnalTmbaKclfheaKydbhCa5hOalhQcbhAincbaeydbgLaC9RaORbbcpeGEaAfhAaOcefhOaeclfheaLhCaQcufgQmbkaAce4hAkcuadaA9Rcifg9kcx2a9kc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh0asc:Cefasyd;8egecdtfa0BdbasaecefBd;8ecua9kcdta9kcFFFFi0Ecbyd;y:L:cjbHjjjjbbh9masc:Cefasyd;8egecdtfa9mBdbasaecefBd;8ea3cbyd;y:L:cjbHjjjjbbh9nasc:Cefasyd;8egecdtfa9nBdbasaecefBd;8ealcbyd;y:L:cjbHjjjjbbh9oasc:Cefasyd;8egecdtfa9oBdbasaecefBd;8eaxaxNayJbbjZamclGEg9pa9pN:vh87JbbbbhUdnadak9nmbdna9kci6mbamcjdGh9qaaclth9ra0cwfh9sJbbbbh85JbbbbhUinascNefabadalaHz:cjjjbabh8Acbh3cbh9tinaba9tcdtfh8McbheindnaHa8AaefydbgAcdtghfydbgCaHa8Maec:W:G:cjbfydbcdtfydbgOcdtg8JfydbgQSmba5aOfRbbgYco2a5aAfRbbgLfRb;a:G:cjbg8LaLco2aYfgDRb;a:G:cjbg9cVcFeGTmbdnaQaC9nmbaDRb;W:G:cjbcFeGmekdnaLcufcFeGce0mbaYTmba8EahfydbaO9hmekdnaLTmbaYcufcFeGce0mba8Fa8JfydbaA9hmeka0a3cx2fgCaOaAa9ccFeGgQEBdlaCaAaOaQEBdbaCaQa8LGcb9hBdwa3cefh3kaeclfgecx9hmbkdna9tcifg9tad9pmba8Acxfh8Aa3cifa9k9nmekka3TmdcbhDinaIaHa0aDcx2fghydbgLcdtgCfydbg8Jc8S2fgeIdwa8KahydlgYcx2fgOIdwg8WNaeIdzaOIdbg8XNaeIdaMgRaRMMa8WNaeIdlaOIdlg8YNaeIdCa8WNaeId3MgRaRMMa8YNaeIdba8XNaeIdxa8YNaeIdKMgRaRMMa8XNaeId8KMMM:lhRJbbbbJbbjZaeIdyg8V:va8VJbbbb9BEh8Vdndnahydwg8MmbJFFuuhBxekJbbbbJbbjZaIaHaYcdtfydbc8S2fgeIdyg81:va81Jbbbb9BEaeIdwa8KaLcx2fgOIdwg81NaeIdzaOIdbg80NaeIdaMgBaBMMa81NaeIdlaOIdlgBNaeIdCa81NaeId3Mg81a81MMaBNaeIdba80NaeIdxaBNaeIdKMg81a81MMa80NaeId8KMMM:lNhBka8VaRNh80dnaaTmbagaLc8S2fgAIdwa8WNaAIdza8XNaAIdaMgRaRMMa8WNaAIdla8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaYaa2gQcdtfhOa8RaLaa2g8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaYc8S2fgAIdwa8KaLcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8AcdtfhOa8RaQcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBdndndna5aLfRbbc9:fPibeedkdna8Fa8Ea8EaCfydbaYSEaXaCfydbgQcdtfydbgCcu9hmbaXaYcdtfydbhCkagaQc8S2fgAIdwa8KaCcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaCaa2g8AcdtfhOa8RaQaa2g8JcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaCc8S2fgAIdwa8KaQcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8JcdtfhOa8Ra8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBxdkaXaCfydbgCaLSmbaHaYcdtfydbh8Aindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8ASmekdna8FaQfydbgecuSmbaHaecdtfydba8ASmekaYhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbka80aR:lgRa81aRa819DEaRa9qEMh80aXaQfydbgCaL9hmbkkdna5aYfRbbgeciSmbaecl9hmeka8MTmbaXaYcdtfydbgCaYSmbindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8JSmekdna8FaQfydbgecuSmbaHaecdtfydba8JSmekaLhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaBaR:lgRa81aRa819DEaRa9qEMhBaXaQfydbgCaY9hmbkkahaBa80aBa809DgeEUdwahaLaYaea8Mcb9hGgeEBdlahaYaLaeEBdbaDcefgDa39hmbkascjdfcbcj;qbz:xjjjb8Aa9shea3hOinascjdfaeydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbcefBdbaecxfheaOcufgOmbkcbhecbhOinascjdfaefgAydbhCaAaOBdbaCaOfhOaeclfgecj;qb9hmbkcbhea9shOinascjdfaOydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbgAcefBdba9maAcdtfaeBdbaOcxfhOa3aecefge9hmbkadak9RgAci9Uh9udnalTmbcbhea9nhOinaOaeBdbaOclfhOalaecefge9hmbkkcbh9va9ocbalz:xjjjbh9caAcO9Uh9wa9uce4h9tcbh8Lcbh8Mdnina0a9ma8Mcdtfydbcx2fg8JIdwgRa879Emea8La9u9pmeJFFuuh8Vdna9ta39pmba0a9ma9tcdtfydbcx2fIdwJbb;aZNh8VkdnaRa8V9ETmbaRaU9ETmba8La9w0mdkdna9caHa8JydlgDcdtg9xfg8AydbgAfg9yRbba9caHa8Jydbghcdtg9zfydbgefg9ARbbVmba5ahfRbbh9BdndnaKaecdtfgOclfydbgCaOydbgOSmbaCaO9RhCa8KaAcx2fhLa8Kaecx2fhYaEaOcitfheindna9naeydbcdtfydbgOaASmba9naeclfydbcdtfydbgQaASmbaOaQSmba8KaQcx2fgQIdba8KaOcx2fgOIdbg8W:tgRaYIdlaOIdlg8X:tg80NaQIdla8X:tg8VaYIdba8W:tgBN:tg8YaRaLIdla8X:tg8SNa8VaLIdba8W:tg8UN:tg8XNa8VaYIdwaOIdwg81:tg8ZNaQIdwa81:tg8Wa80N:tg80a8VaLIdwa81:tg83Na8Wa8SN:tg8VNa8WaBNaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmikaecwfheaCcufgCmbkkdndna9Bc99fcFeGce0mba9na9zfaDBdbaXa9zfydbgeahSmeina8AydbhAdndna8EaecdtgOfydbgecuSmbaHaecdtfydbaASmekdna8FaOfydbgecuSmbaHaecdtfydbaASmekaDheka9naOfaeBdbaXaOfydbgeah9hmbxdkkdndna9BcFeGcdSmbaDhexekdna8Fa8Ea8Ea9zfydbaDSEaXa9zfydbghcdtfydbgecu9hmbaXa9xfydbheka9na9zfaDBdbka9nahcdtfaeBdbka9Ace86bba9yce86bba8JIdwgRaUaUaR9DEhUa9vcefh9vcecda9BcFeGceSEa8Lfh8Lxeka9tcefh9tka8Mcefg8Ma39hmbkka9vTmddnalTmbcbhLcbhhindna9nahcdtgefydbgAahSmbaHaAcdtfydbh8AdnahaHaefydb9hg8JmbaIa8Ac8S2fgeaIahc8S2fgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya8NTmba8Na8Acltfgea8NahcltfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxkaaTmbagaAc8S2fgeagahc8S2g8MfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya9raA2hYa8RhOaahCinaOaYfgeaOaLfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8JmbJbbbbJbbjZaIa8MfgeIdygR:vaRJbbbb9BEaeIdwa8Ka8Acx2fgOIdwgRNaeIdzaOIdbg8VNaeIdaMg8Wa8WMMaRNaeIdlaOIdlg8WNaeIdCaRNaeId3MgRaRMMa8WNaeIdba8VNaeIdxa8WNaeIdKMgRaRMMa8VNaeId8KMMM:lNgRa85a85aR9DEh85kaLa9rfhLahcefghal9hmbkcbhOa8EheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8EaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkcbhOa8FheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8FaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkka85aUaaEh85cbhOabhecbhAindnaHa9naeydbcdtfydbgLcdtfydbgCaHa9naeclfydbcdtfydbgYcdtfydbgQSmbaCaHa9naecwfydbcdtfydbg8AcdtfydbghSmbaQahSmbabaOcdtfgCaLBdbaCcwfa8ABdbaCclfaYBdbaOcifhOkaecxfheaAcifgAad6mbkdndnaSmbaOhdxekdnaOak0mbaOhdxekdna86a859FmbaOhdxekJFFuuh86cbhdabhecbhAindna9ia6aeydbgCcdtfydbcdtfIdbgRa859ETmbaeclf8Pdbh9CabadcdtfgQaCBdbaQclfa9C83dbaRa86a86aR9EEh86adcifhdkaecxfheaAcifgAaO6mbkkadak0mbxdkkascNefabadalaHz:cjjjbkdndnadak0mbadhYxekdnaSmbadhYxekdna86a879FmbadhYxekcehQina86Jbb;aZNgRa87aRa879DEh8WJbbbbhRdna9hTmba9ihea9hhOinaeIdbg8VaRa8Va8W9FEaRa8VaR9EEhRaeclfheaOcufgOmbkkJFFuuh86cbhYabhecbhOindna9ia6aeydbgAcdtfydbcdtfIdbg8Va8W9ETmbaeclf8Pdbh9CabaYcdtfgCaABdbaCclfa9C83dba8Va86a86a8V9EEh86aYcifhYkaecxfheaOcifgOad6mbkdnaQaYad9hVceGmbadhYxdkaRaUaUaR9DEhUaYak9nmecbhQaYhda86a879FmbkkdnamcjjjjdGTmba9ocbalz:xjjjbh8AdnaYTmbabheaYhOina8AaeydbgAfce86bba8AaHaAcdtfydbfce86bbaeclfheaOcufgOmbkkascNefabaYalaHz:cjjjbdndnalTmbcbhCindna8AaCfRbbTmbdna5aCfRbbPlbeebekdnaHaCcdtgLfydbgeaCSmba8KaCcx2fgOa8Kaecx2fgeydwBdwaOae8Pdb83dbxekaIaCc8S2fgQIdygnanJL:3;rUNgRMh87aQIdwgxaRMh8SaQIdlg9DaRMh8UaQIdbg9EaRMh81aQIdag9FaRa8KaCcx2fg8JIdwg88N:th8ZaQId3g9GaRa8JIdlg89N:th83aQIdKg9Ha8JIdbg8:aRN:th80JbbbbhZaQIdCg9IJbbbbMh85aQIdzg9JJbbbbMhBaQIdxg9KJbbbbMh86dndnaaTmbaChAinJbbbba87agaAc8S2fgOIdygR:vaRJbbbb9BEhRa8RaAaa2cltfheaOIdaa87Na8ZMh8ZaOId3a87Na83Mh83aOIdKa87Na80Mh80aOIdCa87Na85Mh85aOIdza87NaBMhBaOIdxa87Na86Mh86aOIdwa87Na8SMh8SaOIdla87Na8UMh8UaOIdba87Na81Mh81aahOina8ZaecwfIdbg8VaecxfIdbg8YNaRN:th8Za83aeclfIdbg8Wa8YNaRN:th83a85a8Wa8VNaRN:th85a81aeIdbg8Xa8XNaRN:th81a80a8Xa8YNaRN:th80aBa8Xa8VNaRN:thBa86a8Xa8WNaRN:th86a8Sa8Va8VNaRN:th8Sa8Ua8Wa8WNaRN:th8UaeczfheaOcufgOmbkaXaAcdtfydbgAaC9hmbka8NTmba8NaCcltfgeIdxhTaeIdwhcaeIdlhJaeIdbhRxekJbbbbhTJbbbbhcJbbbbhJJbbbbhRkaBa81:vg8Wa80Na8Z:ta85aBa86a81:vg8VN:tg8Za8Ua86a8VN:tg8Y:vg8Xa8Va80Na83:tg8UN:th83acaRa8WN:taJaRa8VN:tg86a8XN:tg85a8SaBa8WN:ta8Za8XN:tgB:vg8S:mh8Za86a8Y:vgc:mhJdnJbbbbaRaRa81:vg9eN:ta86acN:ta85a8SN:tg86:la87J:983:g81NgR9ETmba8Za83NaJa8UNa9ea80NaT:tMMa86:vhZka81:laR9ETmba8Y:laR9ETmbaB:laR9ETmba9e:maZNa8W:ma8ZaZNa83aB:vMgBNa8V:maJaZNa8X:maBNa8Ua8Y:vMMg85Na80:ma81:vMMMh87aKaLfgeclfydbgOaeydbge9RhhaEaecitfhLJbbbbhRdnaOaeSg8MmbJbbbbhRaLheahhAina8Kaeclfydbcx2fgOIdwa88:tg8Va8VNaOIdba8::tg8Va8VNaOIdla89:tg8Va8VNMMg8Va8Kaeydbcx2fgOIdwa88:tg8Wa8WNaOIdba8::tg8Wa8WNaOIdla89:tg8Wa8WNMMg8WaRaRa8W9DEgRaRa8V9DEhRaecwfheaAcufgAmbkaR:rgRaRNhRkaBa88:tg8Va8VNa87a8::tg8Va8VNa85a89:tg8Va8VNMMaR9EmbaQId8KhZdna8Mmbina8KaLclfydbcx2fgeIdba8KaLydbcx2fgOIdbg8W:tgRa89aOIdlg8X:tg80NaeIdla8X:tg8Va8:a8W:tg86N:tg8YaRa85a8X:tg8SNa8Va87a8W:tg8UN:tg8XNa8Va88aOIdwg81:tg8ZNaeIdwa81:tg8Wa80N:tg80a8VaBa81:tg83Na8Wa8SN:tg8VNa8Wa86NaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmdaLcwfhLahcufghmbkkJbbbbJbbjZan:vanJbbbb9BEgRaxaBNa9Ja87Na9FMg8Va8VMMaBNa9Da85Na9IaBNa9GMg8Va8VMMa85Na9Ea87Na9Ka85Na9HMg8Va8VMMa87NaZMMM:lNaRaxa88Na9Ja8:Na9FMg8Va8VMMa88Na9Da89Na9Ia88Na9GMg8Va8VMMa89Na9Ea8:Na9Ka89Na9HMg8Va8VMMa8:NaZMMM:lNJbb;aZNJ:983:g81M9Emba8JaBUdwa8Ja85Udla8Ja87UdbkaCcefgCal9hmbkdnaambcbhaxdkcbhQindna8AaQfRbbTmbaHaQcdtgefydbaQ9hmba5aQfhhaXaefh8Ja8KaQcx2fhAa8PaQaa2cdtfh8McbhEincuhCdnahRbbc99fcFeGce0mbaQhCa8JydbgeaQSmba8PaEcdtgOfhLa8MaOfIdbhRaQhCinaChOcuhCdnaLaeaa2cdtfIdbaR9CmbaOcuSmbaOhCagaec8S2fIdyagaOc8S2fIdy9ETmbaehCkaXaecdtfydbgeaQ9hmbkka8PaEcdtfhLa8RaEcltfhKaQheinaLaeaa2cdtfJbbbbJbbjZagaeaCaCcuSEgOc8S2fIdygR:vaRJbbbb9BEaKaOaa2cltfgOIdwaAIdwNaOIdbaAIdbNaOIdlaAIdlNMMaOIdxMNUdbaXaecdtfydbgeaQ9hmbkaEcefgEaa9hmbkkaQcefgQal9hmbxdkkaambcbhakaiavaoarawaaala8Ka8Pazasayasc1efa5a8Aaqz:hjjjbkdnamcjjjjlGTmbazmbaYTmbabhecbhLina5aeydbgAfRbbc3thQaecwfgXydbhHcjjjj94hCdna8EaAcdtgEfydbaeclfgKydbgOSmbcjjjj94cba8FaOcdtfydbaASEhCkaeaQaCVaAVBdba5aOfRbbc3thacjjjj94hCcjjjj94hQdna8EaOcdtfydbaHSmbcjjjj94cba8FaHcdtfydbaOSEhQkaKaaaQVaOVBdba5aHfRbbc3thOdna8EaHcdtfydbaASmbcjjjj94cba8FaEfydbaHSEhCkaXaOaCVaHVBdbaecxfheaLcifgLaY6mbkkdnazTmbaYTmbaYheinabazabydbcdtfydbBdbabclfhbaecufgembkkdnaPTmbaPa9paU:rNUdbkdnasyd;8egHTmbaHcdtasc:Ceffc98fheinaeydbcbyd;C:L:cjbH:bjjjbbaec98fheaHcufgHmbkkascj;sbf8KjjjjbaYk;Yieouabydlhvabydbclfcbaicdtz:xjjjbhoadci9UhrdnadTmbdnalTmbaehwadhDinaoalawydbcdtfydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbxdkkaehwadhDinaoawydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbkkdnaiTmbcbhDaohwinawydbhqawaDBdbawclfhwaqaDfhDaicufgimbkkdnadci6mbinaecwfydbhwaeclfydbhDaeydbhidnalTmbalawcdtfydbhwalaDcdtfydbhDalaicdtfydbhikavaoaicdtfgqydbcitfaDBdbavaqydbcitfawBdlaqaqydbcefBdbavaoaDcdtfgqydbcitfawBdbavaqydbcitfaiBdlaqaqydbcefBdbavaoawcdtfgwydbcitfaiBdbavawydbcitfaDBdlawawydbcefBdbaecxfhearcufgrmbkkabydbcbBdbk:todDue99aicd4aifhrcehwinawgDcethwaDar6mbkcuaDcdtgraDcFFFFi0Ecbyd;y:L:cjbHjjjjbbhwaoaoyd9GgqcefBd9GaoaqcdtfawBdbawcFearz:xjjjbhkdnaiTmbalcd4hlaDcufhxcbhminamhDdnavTmbavamcdtfydbhDkcbadaDal2cdtfgDydlgwawcjjjj94SEgwcH4aw7c:F:b:DD2cbaDydbgwawcjjjj94SEgwcH4aw7c;D;O:B8J27cbaDydwgDaDcjjjj94SEgDcH4aD7c:3F;N8N27axGhwamcdthPdndndnavTmbakawcdtfgrydbgDcuSmeadavaPfydbal2cdtfgsIdbhzcehqinaqhrdnadavaDcdtfydbal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmlkarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbxdkkakawcdtfgrydbgDcuSmbadamal2cdtfgsIdbhzcehqinaqhrdnadaDal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmikarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbkkaramBdbamhDkabaPfaDBdbamcefgmai9hmbkkakcbyd;C:L:cjbH:bjjjbbaoaoyd9GcufBd9GdnaeTmbaiTmbcbhDaehwinawaDBdbawclfhwaiaDcefgD9hmbkcbhDaehwindnaDabydbgrSmbawaearcdtfgrydbBdbaraDBdbkabclfhbawclfhwaiaDcefgD9hmbkkk;:odvuv998Jjjjjbca9Rgocbyd1:G:cjbBdKaocb8Pdj:G:cjb83izaocbydN:G:cjbBdwaocb8Pd:m:G:cjb83ibdnadTmbaicd4hrdnabmbdnalTmbcbhwinaealawcdtfydbar2cdtfhDcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxikkarcdthwcbhDincbhiinaoczfaifgqaeaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaeawfheaDcefgDad9hmbxdkkdnalTmbcbhwinabawcx2fgiaealawcdtfydbar2cdtfgDIdbUdbaiaDIdlUdlaiaDIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxdkkarcdthlcbhwaehDinabawcx2fgiaeawar2cdtfgqIdbUdbaiaqIdlUdlaiaqIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaDalfhDawcefgwad9hmbkkJbbbbaoIdbaoIdzgx:tgkakJbbbb9DEgkaoIdlaoIdCgm:tgPaPak9DEgkaoIdwaoIdKgP:tgsasak9DEhsdnabTmbadTmbJbbbbJbbjZas:vasJbbbb9BEhkinabakabIdbax:tNUdbabclfgoakaoIdbam:tNUdbabcwfgoakaoIdbaP:tNUdbabcxfhbadcufgdmbkkdnavTmbavaPUdwavamUdlavaxUdbkask:WlewudnaeTmbcbhvabhoinaoavBdbaoclfhoaeavcefgv9hmbkkdnaiTmbcbhrinadarcdtfhwcbhDinalawaDcdtgvyd:G:G:cjbcdtfydbcdtfydbhodnalawavfydbcdtfydbgqabaqcdtfgkydbgvSmbinakabavgqcdtfgxydbgvBdbaxhkaqav9hmbkkdnaoabaocdtfgkydbgvSmbinakabavgocdtfgxydbgvBdbaxhkaoav9hmbkkdnaqaoSmbabaqaoaqao0Ecdtfaqaoaqao6EBdbkaDcefgDci9hmbkarcifgrai6mbkkdnaembcbskcbhxindnalaxcdtgvfydbax9hmbaxhodnaxabavfgDydbgvSmbaDhqinaqabavgocdtfgkydbgvBdbakhqaoav9hmbkkaDaoBdbkaxcefgxae9hmbkcbhkabhvcbhoindndnaoalydbgq9hmbdnaoavydbgq9hmbavakBdbakcefhkxdkavabaqcdtfydbBdbxekavabaqcdtfydbBdbkalclfhlavclfhvaeaocefgo9hmbkakk;jiilud99euabcbaecltz:xjjjbhvdnalTmbadhoaihralhwinarcwfIdbhDarclfIdbhqavaoydbcltfgkarIdbakIdbMUdbakaqakIdlMUdlakaDakIdwMUdwakakIdxJbbjZMUdxaoclfhoarcxfhrawcufgwmbkkdnaeTmbavhkaehrinakcxfgoIdbhDaocbBdbakakIdbJbbbbJbbjZaD:vaDJbbbb9BEgDNUdbakclfgoaDaoIdbNUdbakcwfgoaDaoIdbNUdbakczfhkarcufgrmbkkdnalTmbinavadydbcltfgkaicwfIdbakIdw:tgDaDNaiIdbakIdb:tgDaDNaiclfIdbakIdl:tgDaDNMMgDakIdxgqaqaD9DEUdxadclfhdaicxfhialcufglmbkkdnaeTmbavcxfhkinabakIdbUdbakczfhkabclfhbaecufgembkkk:moerudnaoTmbaecd4hzdnavTmbaicd4hHavcdthOcbhAindnaPaAfRbbTmbaAhednaDTmbaDaAcdtfydbhekdnasTmbasaefRbbceGmekdnamaAfRbbcvSmbabaeaz2cdtfgiaraAcx2fgCIdbakNaxIdbMUdbaiaCIdlakNaxIdlMUdlaiaCIdwakNaxIdwMUdwkadaeaH2cdtfhXaqheawhiavhCinaXaeydbcdtgQfaiIdbalaQfIdb:vUdbaeclfheaiclfhiaCcufgCmbkkawaOfhwaAcefgAao9hmbxdkkdnasmbcbheaDhiindnaPaefRbbTmbaehCdnaDTmbaiydbhCkamaefRbbcvSmbabaCaz2cdtfgCarIdbakNaxIdbMUdbaCarclfIdbakNaxIdlMUdlaCarcwfIdbakNaxIdwMUdwkaiclfhiarcxfhraoaecefge9hmbxdkkdnaDTmbindnaPRbbTmbasaDydbgefRbbceGmbamRbbcvSmbabaeaz2cdtfgearIdbakNaxIdbMUdbaearclfIdbakNaxIdlMUdlaearcwfIdbakNaxIdwMUdwkaPcefhPaDclfhDamcefhmarcxfhraocufgombxdkkazcdthicbheindnaPaefRbbTmbasaefRbbceGmbamaefRbbcvSmbabarIdbakNaxIdbMUdbabclfarclfIdbakNaxIdlMUdbabcwfarcwfIdbakNaxIdwMUdbkarcxfhrabaifhbaoaecefge9hmbkkk8MbabaeadaialavcbcbcbcbcbaoarawaDz:bjjjbk8MbabaeadaialavaoarawaDaqakaxamaPz:bjjjbkRbababaeadaialavaoarawaDaqakaxcjjjjdVamz:bjjjbk:vgoque99due99duq998Jjjjjbc;Wb9Rgq8Kjjjjbcbhkaqcxfcbc;Kbz:xjjjb8Aaqcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgxBdxaqceBd2axaialavcbcbz:ejjjb8AaqcualcdtalcFFFFi0Egmcbyd;y:L:cjbHjjjjbbgiBdzaqcdBd2dndnJFF959eJbbjZawJbbjZawJbbjZ9DE:vawJ9VO:d869DEgw:lJbbb9p9DTmbaw:OhPxekcjjjj94hPkadci9Uhsarco9UhzdndnaombaPcd9imekdnalTmbaPcuf:YhwdnaoTmbcbhvaihHaxhOindndnaoavfRbbceGTmbavcjjjjlVhAxekdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHaOcxfhOalavcefgv9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkadTmbcbhkaehvcbhOinakaiavclfydbcdtfydbgHaiavcwfydbcdtfydbgA9haiavydbcdtfydbgXaH9haXaA9hGGfhkavcxfhvaOcifgOad6mbkkarci9UhQdndnaz:Z:rJbbbZMgw:lJbbb9p9DTmbaw:Ohvxekcjjjj94hvkaQ:ZhLcbhKc:bwhzdninakaQ9pmeazaP9Rcd9imeavazcufgOavaO9iEaPcefavaP9kEhYdnalTmbaYcuf:YhwdnaoTmbcbhOaihHaxhvindndnaoaOfRbbceGTmbaOcjjjjlVhAxekdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHavcxfhvalaOcefgO9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkcbhOdnadTmbaehvcbhHinaOaiavclfydbcdtfydbgAaiavcwfydbcdtfydbgX9haiavydbcdtfydbgraA9haraX9hGGfhOavcxfhvaHcifgHad6mbkkdnas:ZgCaL:taY:Ygwaz:Y:tg8ANak:ZgEaO:Zg3:tNaEaL:tawaP:Y:tg5Na3aC:tNMg8EJbbbb9BmbaCaE:ta5a8Aa3aL:tNNNa8E:vawMhwkdndnaOaQ0mbaOhkaYhPxekaOhsaYhzkdndnaKcl0mbdnawJbbbZMgw:lJbbb9p9DTmbaw:Ohvxdkcjjjj94hvxekaPazfcd9ThvkaKcefgKcs9hmbkkdndndnakmbJbbjZhwcbhOcdhvaDmexdkalcd4alfhHcehOinaOgvcethOavaH6mbkaqcuavcdtavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgYBdCaqciBd2aqamcbyd;y:L:cjbHjjjjbbgzBdKaqclBd2dnalTmbaPcuf:YhwdnaoTmbcbhOaihAaxhHindndnaoaOfRbbceGTmbaOcjjjjlVhXxekdndnaHclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqthXdndnaHcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarVhXdndnaHIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarcCtVhXkaAaXBdbaAclfhAaHcxfhHalaOcefgO9hmbxdkkaxhOaihHalhAindndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcCthXdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkarcqtaXVhXdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaHaXarVBdbaOcxfhOaHclfhHaAcufgAmbkkaqcuaYavazaialz:mjjjbgXc8S2gvaXc;D;O;f8U0Ecbyd;y:L:cjbHjjjjbbgiBd3aqcvBd2aicbavz:xjjjbhOdnadTmbcbhraehiinaxaiclfydbgocx2fgvIdbaxaiydbgPcx2fgHIdbg3:tgCaxaicwfydbgYcx2fgAIdlaHIdlg8A:tgwNavIdla8A:tgEaAIdba3:tg8EN:tgLaLNaEaAIdwaHIdwg5:tg8FNavIdwa5:tgEawN:tgwawNaEa8ENaCa8FN:tgCaCNMMg8E:rhEJbbnnJbbjZazaPcdtfydbgvazaocdtfydbgASavazaYcdtfydbgoSGgHEh8Fdna8EJbbbb9ETmbaLaE:vhLaCaE:vhCawaE:vhwkaOavc8S2fgvavIdbawa8FaE:rNgEawNNg8FMUdbavaCaEaCNgaNghavIdlMUdlavaLaEaLNg8ENggavIdwMUdwavawaaNgaavIdxMUdxava8EawNg8JavIdzMUdzavaCa8ENg8EavIdCMUdCavawaEaLa5Nawa3Na8AaCNMM:mg8ANg3NgwavIdKMUdKavaCa3NgCavId3MUd3avaLa3NgLavIdaMUdaava3a8ANg3avId8KMUd8KavaEavIdyMUdydnaHmbaOaAc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdyaOaoc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdykaicxfhiarcifgrad6mbkkcbhAaqcuaXcdtgvaXcFFFFi0Egicbyd;y:L:cjbHjjjjbbgHBdaaqcoBd2aqaicbyd;y:L:cjbHjjjjbbgiBd8KaqcrBd2aHcFeavz:xjjjbhPdnalTmbazhHinJbbbbJbbjZaOaHydbgrc8S2fgvIdygw:vawJbbbb9BEavIdwaxcwfIdbgwNavIdzaxIdbgCNavIdaMgLaLMMawNavIdlaxclfIdbgLNavIdCawNavId3MgwawMMaLNavIdbaCNavIdxaLNavIdKMgwawMMaCNavId8KMMM:lNhwdndnaParcdtgvfgrydbcuSmbaiavfIdbaw9ETmekaraABdbaiavfawUdbkaHclfhHaxcxfhxalaAcefgA9hmbkkdndnaXmbJbbbbhwxekJbbbbhwinaiIdbgCawawaC9DEhwaiclfhiaXcufgXmbkaw:rhwkakcd4akfhOcehiinaigvcethiavaO6mbkcbhOaqcuavcdtgiavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgHBdyaHcFeaiz:xjjjbhXdnadTmbavcufhrcbhkcbhxindnazaeaxcdtfgvydbcdtfydbgiazavclfydbcdtfydbgOSmbaiazavcwfydbcdtfydbgvSmbaOavSmbaPavcdtfydbhAdndnaPaOcdtfydbgvaPaicdtfydbgi9pmbavaA9pmbaAhlaihoavhAxekdnaAai9pmbaAav9pmbaihlavhoxekavhlaAhoaihAkabakcx2fgvaABdbavcwfaoBdbavclfalBdbdnaXaoc:3F;N8N2alc:F:b:DD27aAc;D;O:B8J27arGgOcdtfgvydbgicuSmbcehHinaHhvdnabaicx2fgiydbaA9hmbaiydlal9hmbaiydwaoSmikavcefhHaXaOavfarGgOcdtfgvydbgicu9hmbkkavakBdbakcefhkkaxcifgxad6mbkakci2hOkcwhvaDTmekaDawUdbkavcdthvaqcxfc98fhiinaiavfydbcbyd;C:L:cjbH:bjjjbbavc98fgvmbkaqc;Wbf8KjjjjbaOk:0iewuabcFeaecdtz:xjjjbhbdnalmbcbskaecufhvdndnaiTmbcbhocbhrindndndnabaiarcdtgwfydbgDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbceheinaiaxcdtgxfydbaDSmdaqaefhxaecefheabaxavGgqcdtfgkydbgxcu9hmbkkakarBdbaoheaocefhoxekadaxfydbhekadawfaeBdbarcefgral9hmbxdkkcbhocbhDindnabaDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbaxaDSmbceheinabaqaefavGgqcdtfgkydbgxcuSmeaecefheaxaD9hmbkkdndnaxcu9hmbakaDBdbaoheaocefhoxekadaxcdtfydbhekadaDcdtfaeBdbaDcefgDal9hmbkkaok:3ldrue9:8Jjjjjbc;Wb9Rgr8Kjjjjbcbhwarcxfcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkarcualcdtalcFFFFi0EgDcbyd;y:L:cjbHjjjjbbgqBdxarceBd2aqcbaialavcbarcxfz:djjjbcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbhkarcxfaryd2gxcdtfakBdbaraxcefgmBd2akaialavcbcbz:ejjjb8AarcxfamcdtfaDcbyd;y:L:cjbHjjjjbbgiBdbaraxcdfgvBd2arcxfavcdtfcuaialaeadaqz:fjjjbgecltaecjjjjiGEcbyd;y:L:cjbHjjjjbbgqBdbaqaeaiakalz:gjjjbaxcifhkdnadTmbaoaoNhocbhwabhlcbheindnaqaialydbgvcdtfydbcdtfIdbao9ETmbalclf8PdbhPabawcdtfgDavBdbaDclfaP83dbawcifhwkalcxfhlaecifgead6mbkkdnakTmbaxcdtarcxffcwfhlinalydbcbyd;C:L:cjbH:bjjjbbalc98fhlakcufgkmbkkarc;Wbf8Kjjjjbawk;lOoDud99oue99vuv998Jjjjjbc;Wb9Rgw8KjjjjbdndnarmbcbhDxekawcxfcbc;Kbz:xjjjb8Aawcuadcx2adc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgqBdxawceBd2aqaeadaicbcbz:ejjjb8AawcuadcdtadcFFFFi0Egkcbyd;y:L:cjbHjjjjbbgxBdzawcdBd2adcd4adfhecehiinaigmcethiamae6mbkcbhPawcuamcdtgsamcFFFFi0Ecbyd;y:L:cjbHjjjjbbgzBdCawciBd2dndnar:ZgH:rJbbbZMgO:lJbbb9p9DTmbaO:Ohixekcjjjj94hikamcufhAc:bwhCcbhXadhQcbhLinaiaCcufgeaiae9iEaPcefaiaP9kEhDdndnadTmbaDcuf:YhOaqhiaxheadhKindndnaiIdbaONJbbbZMgY:lJbbb9p9DTmbaY:Oh8Axekcjjjj94h8Aka8AcCth8AdndnaiclfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaEcqta8AVh8AdndnaicwfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaea8AaEVBdbaicxfhiaeclfheaKcufgKmbkazcFeasz:xjjjbh3cbh5cbh8Eindna3axa8Ecdtfydbg8Acm4a8A7c:v;t;h;Ev2gics4ai7aAGgKcdtfgEydbgecuSmbaea8ASmbcehiina3aKaifaAGgKcdtfgEydbgecuSmeaicefhiaea8A9hmbkkaEa8ABdba5aecuSfh5a8Ecefg8Ead9hmbxdkkazcFeasz:xjjjb8Acbh5kdnaQ:ZgYaH:taD:YgOaC:Y:tg8FNaX:Zgaa5:Zgh:tNaaaH:taOaP:Y:tggNahaY:tNMg8JJbbbb9BmbaYaa:taga8FahaH:tNNNa8J:vaOMhOkaPaDa5ar0geEhPaXa5aeEhXdna5arSmbaDaCaeEgCaP9Rcd9imbdndnaLcl0mbdnaOJbbbZMgO:lJbbb9p9DTmbaO:Ohixdkcjjjj94hixekaPaCfcd9Thika5aQaeEhQaLcefgLcs9hmekkdndnaXmbcihicbhDxekawakcbyd;y:L:cjbHjjjjbbg8ABdKawclBd2aPcuf:YhYdnadTmbaqhiaxheadhKindndnaiIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:OhExekcjjjj94hEkaEcCthEdndnaiclfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3ka3cqtaEVhEdndnaicwfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3kaeaEa3VBdbaicxfhiaeclfheaKcufgKmbkkawcuazama8Aaxadz:mjjjbgDc32giaDc;j:KM;jb0Ecbyd;y:L:cjbHjjjjbbgeBd3awcvBd2aecbaiz:xjjjbh3avcd4hxdnadTmbdnalTmbaxcdth8Ea8AhEaqhealhKadhAina3aEydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaKIdbaiIdxMUdxaiaKclfIdbaiIdzMUdzaiaKcwfIdbaiIdCMUdCaiaiIdKJbbjZMUdKaEclfhEaecxfheaKa8EfhKaAcufgAmbxdkka8AhKaqheadhEina3aKydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaiIdxJbbbbMUdxaiaiIdzJbbbbMUdzaiaiIdCJbbbbMUdCaiaiIdKJbbjZMUdKaKclfhKaecxfheaEcufgEmbkkdnaDTmba3hiaDheinaiaiIdbJbbbbJbbjZaicKfIdbgO:vaOJbbbb9BEgONUdbaiclfgKaOaKIdbNUdbaicwfgKaOaKIdbNUdbaicxfgKaOaKIdbNUdbaiczfgKaOaKIdbNUdbaicCfgKaOaKIdbNUdbaic3fhiaecufgembkkcbhEawcuaDcdtgCaDcFFFFi0Egicbyd;y:L:cjbHjjjjbbgeBdaawcoBd2awaicbyd;y:L:cjbHjjjjbbg8EBd8KaecFeaCz:xjjjbh5dnadTmbaoJbbjZJbbjZaY:vaPceSENgOaONhYaxcdthxalheinaYaecN:H:cjbalEgKIdwa3a8AydbgAc32fgiIdC:tgOaONaKIdbaiIdx:tgOaONaKIdlaiIdz:tgOaONMMNaqcwfIdbaiIdw:tgOaONaqIdbaiIdb:tgOaONaqclfIdbaiIdl:tgOaONMMMhOdndna5aAcdtgifgKydbcuSmba8EaifIdbaO9ETmekaKaEBdba8EaifaOUdbka8Aclfh8AaqcxfhqaeaxfheadaEcefgE9hmbkkaba5aCz:wjjjb8Acrhikaicdthiawcxfc98fheinaeaifydbcbyd;C:L:cjbH:bjjjbbaic98fgimbkkawc;Wbf8KjjjjbaDk:Pdidui99ducbhi8Jjjjjbca9Rglcbyd1:G:cjbBdKalcb8Pdj:G:cjb83izalcbydN:G:cjbBdwalcb8Pd:m:G:cjb83ibdndnaembJbbjFhvJbbjFhoJbbjFhrxekadcd4cdthwincbhdinalczfadfgDabadfIdbgvaDIdbgoaoav9EEUdbaladfgDavaDIdbgoaoav9DEUdbadclfgdcx9hmbkabawfhbaicefgiae9hmbkalIdwalIdK:thralIdlalIdC:thoalIdbalIdz:thvkJbbbbavavJbbbb9DEgvaoaoav9DEgvararav9DEk:H8Modui99lud99Aus998Jjjjjbcji9RgD8KjjjjbcbhqaDcxfcbc;Kbz:xjjjb8AaDcbBdwaD9cb83ibaDcbyd;i:L:cjbBd1eaDcb8Pd;a:L:cjb83ijeaDcbyd;u:L:cjbBd94aDcb8Pd;m:L:cjb83i9WdndnavmbJbbjFhkJbbjFhxJbbjFhmxekaocd4cdthPalhsincbhzinaDcjefazfgHasazfIdbgkaHIdbgxaxak9EEUdbaDc;WbfazfgHakaHIdbgxaxak9DEUdbazclfgzcx9hmbkasaPfhsaqcefgqav9hmbkaDId94aDId1e:thmaDIdtaDId:ee:thxaDId9WaDIdje:thkkJbbbbhOdnar:YgAJq;x8J88MaA:vJbbbbakakJbbbb9DEgkaxaxak9DEgkamamak9DENgxJbbbb9Bmbarc9:f:Yax:vhOkaDcCfhCaDcxfcxfhXcbhzinaDazfaDcjefazfIdbgkaxaDc;WbfazfIdbak:t:tJbbb:;NMUdbazclfgzcx9hmbkcbhQaDarar2gLar2gzcbyd;y:L:cjbHjjjjbbgHBdxaDceBd2aHcbazz:xjjjbgKcbcbadaialaoaraOaDawz:rjjjbcdhYaDcuaLcdtaLcFFFFi0Eg8Acbyd;y:L:cjbHjjjjbbgEBdzaDcdBd2aDcjefcbarz:xjjjb8Acbh3dnaLTmbdnarcb9kmbaKhzaEhHaLhsincbh3aHcbcuazaDcjefarz:AjjjbEBdbazarfhzaHclfhHascufgsmbxdkkaKhPcbh3cbhvindndnaKavar2faDcjefarz:AjjjbTmbcbhHaPhzarhsinazaHazRbbgqfgHcbaqE86bbazcefhzascufgsmbkaEavcdtfa3BdbaHa3fh3xekaEavcdtfcuBdbkaParfhPavcefgvaL9hmbkkdnabTmbaDcua3cotgza3cFFF8F0Ecbyd;y:L:cjbHjjjjbbgQBdCcihYaDciBd2aQcbazz:xjjjb8AaXhCkdnawceGmbaCa8Acbyd;y:L:cjbHjjjjbbg5BdbaDaYcefgzBd2aDcxfazcdtfaLcbyd;y:L:cjbHjjjjbbgzBdbaDaYcdfgYBd2azcbaLz:xjjjbh8EarcufhXdnarci9imbarc9:fhCararcef2aKfcefh8Aceh8Fina8Far2hPa8AhvcehqindnaEaqaPfcdtfydbcuSmbavhzaChHinazazRbbgscuasE86bbazcefhzaHcufgHmbkkavarfhvaqcefgqaX9hmbka8AaLfh8Aa8Fcefg8FaX9hmbkkarce9imbcbh8Acbhqcbhvina8EaqfhscbhzindnasazfgHRbbmbaHce86bba5a8AcdtfaqazfBdba8Acefh8Akarazcefgz9hmbkaqarfhqavcefgvar9hmbka8ATmbaKcefhaaKc9:fhharc9:fhgarci9ih8Jina8Ea5a8Acufg8Acdtfydbgvfcb86bbavar2hPdna8JmbaEavcdtfydbcuSmbaKaPfhHaghqindnaHcefgzRbbgscFe9hmbaHRbbmbcbhskazas86bbazhHaqcufgqmbkaharavcef2fhzaXhsindnazRbbgHcFe9hmbazcefRbbmbcbhHkazaH86bbazcufhzascufgsce9kmbkkaaaPfh8Kavavar9Ug8Lar29Rh8FcbhCindnaCceScuaCEa8Ffgzce9imbazaX9ombcuaCciSaCcdSEa8LfgHce9imbaHaX9ombaEaHar2azfg8McdtfydbcuSmba8Jmbaaa8Mar2fhzcbhqa8KhsaghvinazazRbbgHcbaHaHcFeSEasRbbEgP86bbascefhsazcefhzaPaH7aqVhqavcufgvmbkaqcFeGTmba8Ea8MfgzRbbmbazce86bba5a8Acdtfa8MBdba8Acefh8AkaCcefgCcl9hmbka8AmbkkdnaQTmbaKaEaQadaialaoaraOaDawz:rjjjba3TmbJbbjZaO:vhkawcjjjjlGhPdnawcdGTmbJbbnnaOaON:vh8NakJbbbZNhyaQhzinazczfgsIdbg8PazcCfIdbgx:vhmazcxfgqIdbgIax:vhAazcwfgvIdbg8Rax:vh8SakazydbgHcFrG:ZNhRakaHcq4cFrG:ZNh8UakaHcC4cFrG:ZNh8VdnaxJ:p;c;188Ng8WazcKfIdbMg8X:laxJ:983:g81Ngx9ETmba8Wazc3fIdbMazc8KfIdbg8Ya8Ya8X:vg8YN:tg8Z:lax9ETmba8WazcafIdbMazcyfIdbg8Wa8Wa8X:vg80N:tazc8SfIdba8Wa8YN:tg8Wa8Wa8Z:vg8WN:tg81:lax9ETmba8PJ:p;c;188NazcUfIdb:ta80a8RJ:p;c;188Nazc8WfIdb:tg8PN:ta8WaIJ:p;c;188Nazc80fIdb:ta8Ya8PN:tgIN:ta81:vgxam:tg8Ra8RNa8Pa8X:va8YaIa8Z:va8WaxN:tg8XN:ta80axN:tg8Wa8S:tg8Ya8YNa8XaA:tg8Ya8YNMMa8N9DTmbaxaRaxaR9EEgxakaRMgmaxam9DEhma8Xa8Ua8Xa8U9EEgxaka8UMgAaxaA9DEhAa8Wa8Va8Wa8V9EEgxaka8VMg8Saxa8S9DEh8SkdnaPTmbayaRMhmaya8UMhAaya8VMh8SkasamUdbaqaAUdbava8SUdbazc;abfhza3cufg3mbxdkkdnaPTmbakJbbbZNhxaQhzinazczfaxakazydbgHcFrG:ZNMUdbazcxfaxakaHcq4cFrG:ZNMUdbazcwfaxakaHcC4cFrG:ZNMUdbazc;abfhza3cufg3mbxdkkaQcCfhzinazc98fgHaHIdbazIdbgk:vUdbazc94fgHaHIdbak:vUdbazctfgHaHIdbak:vUdbazc;abfhza3cufg3mbkkcbhsdndnarcd9imbarcufh3aEarcdtfhadnabmbaKcefg8Mararcefgz2fh8JaKazfhba8MaLfh8Ecbhscbh8Kina8Kar2h8La8Mheabh8Aa8Eh8Fa8Jh5cbhXindnaEaXa8LfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbclcbaKaqar2fgzarfRbbEazRbbcb9hVczcbazaLfgzRbbEVc;abcbazarfRbbEVhPaehza8AhHa8Fhqa5hva3hQindnaPclcbaHRbbEazRbbcb9hVczcbaqRbbEVc;abcbavRbbEVgPcetVgCTmbaCcFeSmbasaCRb;W;p:cjbfhskazcefhzaHcefhHaqcefhqavcefhvaQcufgQmbkkaearfhea8Aarfh8Aa8Farfh8Fa5arfh5aXcefgXa39hmbka8MaLfh8MabaLfhba8EaLfh8Ea8JaLfh8Ja8Kcefg8Ka39hmbxdkkJbbjZaO:vgkakJk;x8J88NNh8RawcdGh8EaDIdwhkaDIdlhxaDIdbhmcbhscbhPinaPar2h8KcbhvindnaEava8KfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbcbh8AclcbaKaqar2fgYarfRbbEaYRbbcb9hVczcbaYaLfg8JRbbEVc;abcba8JarfRbbEVh8Lindna8LclcbaYa8Ag8Mcefg8AfgzarfRbbEazRbbcb9hVczcba8Ja8AfgzRbbEVc;abcbazarfRbbEVg8LcetVgCTmbaCcFeSmbcbhqdndndnaCRb;W;n:cjbcufPdebdka8ETmeaCcC2gz8Ve;W:L:cjbcltaz8Ve;Y:L:cjbcsGVh8FaKa8Mfh5cxhzaDcjefhHinaHaQaEa8Faz4gqce4ceGavfaqcd4ceGaPfar2fgXcdtfydbcotfa5aqceGfaXar2fRbbcotfcnfBdbaHclfhHazc98fgzc989hmbkaDydjegzIdyaDyd:megHIdyMaDyd:eegqIdyaDyd1egXIdyMMg8XaqIdwaXIdwMJbbbZNgANazIdUaHIdUMaqIdUaXIdUMMg8WMg8Sa8SMazIdaaHIdaMaqIdaaXIdaMMg8YaqIdzaXIdzMJbbbZNg8SNMa8SNazId8SaHId8SMaqId8SaXId8SMMgRa8SNazId80aHId80MaqId80aXId80MMg8UMg8Sa8SMazId3aHId3MaqId3aXId3MMg8VaqIdxaXIdxMJbbbZNg8SNMa8SNazId8KaHId8KMaqId8KaXId8KMMg8Za8SNazId8WaHId8WMaqId8WaXId8WMMg80Mg8Sa8SMazIdKaHIdKMaqIdKaXIdKMMgyaANMaANazId88aHId88MaqId88aXId88MMg8PMMM:lgIa8RazIdCaHIdCMaqIdCaXIdCMMN9Ea8XazIdwaHIdwMJbbbZNgANa8WMg8Sa8SMa8YazIdzaHIdzMJbbbZNg8SNMa8SNaRa8SNa8UMg8Sa8SMa8VazIdxaHIdxMJbbbZNg8SNMa8SNa8Za8SNa80Mg8Sa8SMayaANMaANa8PMMM:laIJ;d;1UZN9DGhqxekaKa8Mfh8FcbhzcrhHindnaCaz4ceGTmba8FazceGfazce4ceGavfazcd4aPfar2fgqar2fRbbgXcFeSmbaQaEaqcdtfydbcotfaXcotfc9efRbbaH4ceGTmbcbhqxdkaHcufhHcehqazcefgzcw9hmbkkaCcC2aqcq2fgH8Ve;W:L:cjbgzTmbaHc;Y:L:cjbfhqaKa8MfhCabasc8K2fhHindnasae9pmbaHaQaEazcD4ceGavfazcq4ceGaPfar2fgXcdtfydbcotfaCazcw4ceGfaXar2fRbbcotfgXc9ifIdbamMUdbaHclfaXc9mfIdbaxMUdbaHcwfaXc9qfIdbakMUdbaHcxfamaQaEazcv4ceGavfazco4ceGaPfar2fgXcdtfydbcotfaCazcl4ceGfaXar2fRbbcotfgXc9ifIdbMUdbaHczfaxaXc9mfIdbMUdbaHcCfakaXc9qfIdbMUdbaHcKfamaQaEazce4ceGavfazcd4ceGaPfar2fgXcdtfydbcotfaCazceGfaXar2fRbbcotfgzc9ifIdbMUdbaHc3faxazc9mfIdbMUdbaHcafakazc9qfIdbMUdbkaHc8KfhHascefhsaq8Vebhzaqcdfhqazmbkka8Aa39hmbkkavcefgva39hmbkaPcefgPa39hmbkaDyd2gYTmekaYcdtaDcxffc98fhzinazydbcbyd;C:L:cjbH:bjjjbbazc98fhzaYcufgYmbkkaDcjif8Kjjjjbask;Kxmiue99due99euz99eui99eud99dud99oudnalTmbaocd4hkaqcdGhxarc99fhqarcethmawawMhPcbhsindndnawavaiascdtfgoclfydbak2cdtfgzIdwgHavaoydbak2cdtfgOIdwgA:tgCaCNazIdbgXaOIdbgQ:tgLaLNazIdlgKaOIdlgY:tg8Aa8ANMMgEavaocwfydbak2cdtfgoIdwg3aA:tg5a5NaoIdbg8EaQ:tg8Fa8FNaoIdlgaaY:tghahNMMggaEag9EEgEa3aH:tgHaHNa8EaX:tgHaHNaaaK:tgHaHNMMgHaEaH9EE:rNgHaHMgH:lJbbb9p9DTmbaH:Ohoxekcjjjj94hokdnaLahNa8Aa8FN:tgHaHNa8Aa5NaCahN:tgXaXNaCa8FNaLa5N:tgKaKNMMg3Jbbbb9BmbJbbjZhEdnaoceaoce9kEgoamaoam9iEg8Jcd9imbJbbjZa8J:Z:vhEkarcb9imbaAaDIdw:th8KaYaDIdl:th8LaQaDIdb:th8Ma8Jcba8Jcb9kEh8NdnadTmbaHJbbjZa3:rgA:vgQNg3aAa8Jcefa8Jcdf2:Y:vgANh8EaKaQNgKaANhyaXaQNgXaXaANNh8PcbhIina8Jcba8Jcb9kEcefh8RaEaI:ZNgQaCNa8KMhgaQa8ANa8LMh8SaQaLNa8MMhRcbhzindndnaPaEaz:ZNgQahNa8SMgYNgH:lJbbb9p9DTmbaH:OhOxekcjjjj94hOkaOce91goaqaoaq6Eh8UdndnaPaQa5NagMgHNga:lJbbb9p9DTmbaa:Oh8Vxekcjjjj94h8Vka8Ua8Vce91goaqaoaq6Eg8Wcefar2fcefgoar2h8XdndnaPaQa8FNaRMgQNga:lJbbb9p9DTmbaa:Oh8Yxekcjjjj94h8Ykadaeaocdtfydbcotfaba8Yce91goaqaoaq6Eg8Zfa8XfcefRbbcotfgocnfa8Ucqta8ZcCtVa8WVBdbaoc9efg8Ua8URbbcea8YceGaOcetcdGVa8VcdtclGVtV86bbaoc9ifgOaQaANaOIdbMUdbaoc9mfgOaYaANaOIdbMUdbaoc9qfgOaHaANaOIdbMUdbaoc9ufgOaAaOIdbMUdbdnaxTmbaoc9yfgOa8PaOIdbMUdbaoc9CfgOaKayNaOIdbMUdbaoc9GfgOa3a8ENaOIdbMUdbaoc9KfgOaXayNaOIdbMUdbaoc9OfgOaXa8ENaOIdbMUdbaoc2fgOaKa8ENaOIdbMUdbaoc9WfgOaXaAa3aHNaXaQNaKaYNMMgY:mNgQNaOIdbMUdbaoctfgOaKaQNaOIdbMUdbaoc94fgOa3aQNaOIdbMUdbaoc98fgoaoIdbaYaQN:tUdbka8Razcefgz9hmbka8Jcufh8JaIa8NShoaIcefhIaoTmbxdkkcbh8Vina8Jcba8Jcb9kEcefh8UaEa8V:ZNgAaCNa8KMhYaAa8ANa8LMhHaAaLNa8MMhXcbhoindndnaPaEao:ZNgAahNaHMNgQ:lJbbb9p9DTmbaQ:Ohzxekcjjjj94hzkazce91gzaqazaq6EhzdndnaPaAa5NaYMNgQ:lJbbb9p9DTmbaQ:OhOxekcjjjj94hOkazaOce91gOaqaOaq6Ecefar2fcefar2hzdndnaPaAa8FNaXMNgA:lJbbb9p9DTmbaA:OhOxekcjjjj94hOkabaOce91gOaqaOaq6Efazfcefce86bba8Uaocefgo9hmbka8Jcufh8Ja8Va8NShoa8Vcefh8VaoTmbkkascifgsal6mbkkk:Nvezu8Jjjjjbcjd9Rgb8Kjjjjbcbheabcbcjdz:xjjjbhdc:W:H:cjbhbinabRbbgicC2glabcqf8Veb87e;4:L:cjbalabcdfgv8Peb83e;W:L:cjbaiabcefRbb86b;W;n:cjbadaifce86bbalavabcxfceaetc:F:d;avGEgi8Peb83e;6:L:cjbalai8Vew87e:c:M:cjbabcQfhbaecefgecK9hmbkcbhoinc;Y:L:cjbhrcbhvindnadavfgwRbbce9hmbavcC2c;W:L:cjbfhDcbhbcehqavc;W;n:cjbfhkinabcitc:G:H:cjbfhlcbhbcbheinaeavab4ceGalabfRbbtVheabcefgbcw9hmbkdnadaecFeGgxfgmRbbmbaxcC2c;W:L:cjbfhPcbhbcehsindnaDabcq2gif8VebgbTmbaraifheaPaifhiinaialabcl4csGfRbbcltalabcw4csGfRbbcwtValabcsGfRbbV87ebaicdfhiae8VebhbaecdfheabmbkkcehbasceGhecbhsaembkamce86bbaxakRbb86b;W;n:cjbkcehbaqceGhlcbhqalmbkawcd86bbkarcCfhravcefgvcjd9hmbkaocefgoci9hmbkcbhic;W:L:cjbhvincuhlavhbinalcefhlab8Vebheabcdfhbaembkaial86b;W;p:cjbavcCfhvaicefgicjd9hmbkadcjdf8Kjjjjbk9DeeuabcFeaicdtz:xjjjbhlcbhbdnadTmbindnalaeydbcdtfgiydbcu9hmbaiabBdbabcefhbkaeclfheadcufgdmbkkabk;Bidqui998Jjjjjbc;Wb9Rgl8Kjjjjbalcxfcbc;Kbz:xjjjb8Aadcd4adfhvcehoinaogrcethoarav6mbkalcuarcdtgoarcFFFFi0Ecbyd;y:L:cjbHjjjjbbgvBdxavcFeaoz:xjjjbhwdnadTmbaicd4hDarcufhqcbhkindndnawcbaeakaD2cdtfgrydlgiaicjjjj94SEgocH4ao7c:F:b:DD2cbarydbgxaxcjjjj94SEgocH4ao7c;D;O:B8J27cbarydwgmamcjjjj94SEgrcH4ar7c:3F;N8N27aqGgvcdtfgrydbgocuSmbam::hPai::hsax::hzcehiinaihrdnaeaoaD2cdtfgiIdbaz9CmbaiIdlas9CmbaiIdwaP9BmikarcefhiawavarfaqGgvcdtfgrydbgocu9hmbkkarakBdbakhokabakcdtfaoBdbakcefgkad9hmbkkalydxcbyd;C:L:cjbH:bjjjbbalc;Wbf8Kjjjjbk9teiucbcbyd;G:L:cjbgeabcifc98GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd;G:L:cjbgeabcrfc94GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd;G:L:cjbge9Rcifc98GaefgbBd;G:L:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akk6eiucbhidnadTmbdninabRbbglaeRbbgv9hmeaecefheabcefhbadcufgdmbxdkkalav9Rhikaikk;0vdbcj:Gdk;yvFFuuFFuuFFuuFFuFFFuFFFuFbbbbbbbbebbbdbbbbbbbebbbebbbdbbbbbbbbbbbeeeeeebebbeebbebbebbbeeebbbbebbbbbbbbbbbbbbbbbbbeeeeeeebebbbeeebbeebbbbbebbbbbebebbbbbbbbbbbbbbbdiorbelvlbodveribbbbbbbbbbbbbbbbbbbbbbebbbbbbbbbbbbbbbbbbbbbibbbbbbbbbbbbbbbbbbbbbobbbbbbbbbbbbbbbbbbbbbrbaebbbbbbbbbbbbbbbbbbsd8We8YbbbbbbbhiaebbbbbbQe8Ke9cebbbbbbbbbbbbbbbbLb8KebbbbbbbbbbbbbbbbbbKbbbbbbbbbbbbbbbbbbbbbYeJbilbbbbbbbbbbbbbbbbEe80e8WlbbbbbbzlAbbbbbbb5eJdnibbbbbbai8Kbbbbbbb8Ee9ce8Ylcibbbb8Yebbbbbbbb8FdOlAdbbbbbb80e8Ylbbbbbb88eTi8KiJv8Jlbbbbbbbbbbbb89e9td8Kv9qibbbbndlvaibbbbZd8Li8KvbbbbbbJdTibbbbbb9Pe81b9GvoiBvbbbbbbbbbbbb9Re9JbvoWibbbbvibbbbbbbb9VeWi9Gvbbbbbb8WvBbbbbbbb9:b9ceBvbbbbbbbbbbbbbbbbubWibbbbbbbbbbbbbbbbbb;Wd9hvSrbbbbbbWl9NvbbbbbbFbbbbbbbbbbbbbbbbbbbbbFFuuFFuuFFuuFFuFFFuFFFuFbc;y:Ldkxebbbdbbb;W:Obb",t=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var e,n=WebAssembly.instantiate(a(i),{}).then(function(p){e=p.instance,e.exports.__wasm_call_ctors()});function a(p){for(var _=new Uint8Array(p.length),M=0;M<p.length;++M){var x=p.charCodeAt(M);_[M]=x>96?x-97:x>64?x-39:x+4}for(var S=0,M=0;M<p.length;++M)_[S++]=_[M]<60?t[_[M]]:(_[M]-60)*64+_[++M];return _.buffer.slice(0,S)}function s(p){if(!p)throw new Error("Assertion failed")}function r(p){return new Uint8Array(p.buffer,p.byteOffset,p.byteLength)}function o(p,_,M,x){var S=e.exports.sbrk,E=S(M*4),A=S(M*x*4),R=new Uint8Array(e.exports.memory.buffer);R.set(r(_),A),p(E,A,M,x*4),R=new Uint8Array(e.exports.memory.buffer);var C=new Uint32Array(M);return new Uint8Array(C.buffer).set(R.subarray(E,E+M*4)),S(E-S(0)),C}function c(p,_,M){var x=e.exports.sbrk,S=x(_.length*4),E=x(M*4),A=new Uint8Array(e.exports.memory.buffer),R=r(_);A.set(R,S);var C=p(E,S,_.length,M);A=new Uint8Array(e.exports.memory.buffer);var L=new Uint32Array(M);new Uint8Array(L.buffer).set(A.subarray(E,E+M*4)),x(S-x(0));for(var N=0;N<_.length;++N)_[N]=L[_[N]];return[L,C]}function l(p){for(var _=0,M=0;M<p.length;++M){var x=p[M];_=_<x?x:_}return _}function h(p,_,M,x,S,E,A,R,C){var L=e.exports.sbrk,N=L(4),U=L(M*4),z=L(S*E),B=L(M*4),K=new Uint8Array(e.exports.memory.buffer);K.set(r(x),z),K.set(r(_),B);var W=p(U,B,M,z,S,E,A,R,C,N);K=new Uint8Array(e.exports.memory.buffer);var Y=new Uint32Array(W);r(Y).set(K.subarray(U,U+W*4));var tt=new Float32Array(1);return r(tt).set(K.subarray(N,N+4)),L(N-L(0)),[Y,tt[0]]}function u(p,_,M,x,S,E,A,R,C,L,N,U,z){var B=e.exports.sbrk,K=B(4),W=B(M*4),Y=B(S*E),tt=B(S*R),gt=B(C.length*4),It=B(M*4),X=L?B(S):0,it=new Uint8Array(e.exports.memory.buffer);it.set(r(x),Y),it.set(r(A),tt),it.set(r(C),gt),it.set(r(_),It),L&&it.set(r(L),X);var _t=p(W,It,M,Y,S,E,tt,R,gt,C.length,X,N,U,z,K);it=new Uint8Array(e.exports.memory.buffer);var Et=new Uint32Array(_t);r(Et).set(it.subarray(W,W+_t*4));var pt=new Float32Array(1);return r(pt).set(it.subarray(K,K+4)),B(K-B(0)),[Et,pt[0]]}function d(p,_,M,x,S,E,A,R,C,L,N,U,z){var B=e.exports.sbrk,K=B(4),W=B(S*E),Y=B(S*R),tt=B(C.length*4),gt=B(M*4),It=L?B(S):0,X=new Uint8Array(e.exports.memory.buffer);X.set(r(x),W),X.set(r(A),Y),X.set(r(C),tt),X.set(r(_),gt),L&&X.set(r(L),It);var it=p(gt,M,W,S,E,Y,R,tt,C.length,It,N,U,z,K);X=new Uint8Array(e.exports.memory.buffer),r(_).set(X.subarray(gt,gt+it*4)),r(x).set(X.subarray(W,W+S*E)),r(A).set(X.subarray(Y,Y+S*R));var _t=new Float32Array(1);return r(_t).set(X.subarray(K,K+4)),B(K-B(0)),[it,_t[0]]}function f(p,_,M,x){var S=e.exports.sbrk,E=S(M*x),A=new Uint8Array(e.exports.memory.buffer);A.set(r(_),E);var R=p(E,M,x);return S(E-S(0)),R}function m(p,_,M,x,S,E,A,R){var C=e.exports.sbrk,L=C(R*4),N=C(M*x),U=S?C(M*E):0,z=new Uint8Array(e.exports.memory.buffer);z.set(r(_),N),S&&z.set(r(S),U);var B=p(L,N,M,x,U,E,A,R);z=new Uint8Array(e.exports.memory.buffer);var K=new Uint32Array(B);return r(K).set(z.subarray(L,L+B*4)),C(L-C(0)),K}function y(p,_,M,x,S,E,A,R,C){var L=e.exports.sbrk,N=L(4),U=L(M*4),z=L(S*E),B=L(M*4),K=A?L(S):0,W=new Uint8Array(e.exports.memory.buffer);W.set(r(x),z),W.set(r(_),B),A&&W.set(r(A),K);var Y=p(U,B,M,z,S,E,K,R,C,N);W=new Uint8Array(e.exports.memory.buffer);var tt=new Uint32Array(Y);r(tt).set(W.subarray(U,U+Y*4));var gt=new Float32Array(1);return r(gt).set(W.subarray(N,N+4)),L(N-L(0)),[tt,gt[0]]}function g(p,_,M,x,S,E,A){var R=e.exports.sbrk,C=R(M*4),L=R(S*E),N=R(M*4),U=new Uint8Array(e.exports.memory.buffer);U.set(r(x),L),U.set(r(_),N);var z=p(C,N,M,L,S,E,A);U=new Uint8Array(e.exports.memory.buffer);var B=new Uint32Array(z);return r(B).set(U.subarray(C,C+z*4)),R(C-R(0)),B}function b(p,_,M,x,S,E){var A=e.exports.sbrk,R=A(M.byteLength),C=A(_.byteLength),L=new Uint8Array(e.exports.memory.buffer);L.set(r(M),R),L.set(r(_),C);var N=M.byteLength/x,U=p(0,0,C,_.length,R,N,x,S,E),z=A(U*9*4),B=p(z,U,C,_.length,R,N,x,S,E);s(B<=U),L=new Uint8Array(e.exports.memory.buffer);var K=new Float32Array(B*9);return r(K).set(L.subarray(z,z+K.byteLength)),A(R-A(0)),K}var v={LockBorder:1,Sparse:2,ErrorAbsolute:4,Prune:8,Regularize:16,Permissive:32,RegularizeLight:64,PreserveFolds:128,ErrorClamped:256,_InternalDebug:1<<30},w={Shell:1,Solve:2,Thicken:0,_InternalDebug:1<<30};return{ready:n,supported:!0,compactMesh:function(p){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0);var _=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),M=c(e.exports.meshopt_optimizeVertexFetchRemap,_,l(p)+1);if(p!==_)for(var x=0;x<_.length;++x)p[x]=_[x];return M},generatePositionRemap:function(p,_){return s(p instanceof Float32Array),s(p.length%_==0),s(_>=3),o(e.exports.meshopt_generatePositionRemap,p,p.length/_,_)},simplify:function(p,_,M,x,S,E){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%M==0),s(M>=3),s(x>=0&&x<=p.length),s(x%3==0),s(S>=0);for(var A=0,R=0;R<(E?E.length:0);++R)s(E[R]in v),A|=v[E[R]];var C=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),L=h(e.exports.meshopt_simplify,C,p.length,_,_.length/M,M*4,x,S,A);return L[0]=p instanceof Uint32Array?L[0]:new p.constructor(L[0]),L},simplifyWithAttributes:function(p,_,M,x,S,E,A,R,C,L){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%M==0),s(M>=3),s(x instanceof Float32Array),s(x.length==S*(_.length/M)),s(S>=0),s(A==null||A instanceof Uint8Array),s(A==null||A.length==_.length/M),s(R>=0&&R<=p.length),s(R%3==0),s(C>=0),s(Array.isArray(E)),s(S>=E.length),s(E.length<=32);for(var N=0;N<E.length;++N)s(E[N]>=0);for(var U=0,N=0;N<(L?L.length:0);++N)s(L[N]in v),U|=v[L[N]];var z=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),B=u(e.exports.meshopt_simplifyWithAttributes,z,p.length,_,_.length/M,M*4,x,S*4,new Float32Array(E),A,R,C,U);return B[0]=p instanceof Uint32Array?B[0]:new p.constructor(B[0]),B},simplifyWithUpdate:function(p,_,M,x,S,E,A,R,C,L){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%M==0),s(M>=3),s(x instanceof Float32Array),s(x.length==S*(_.length/M)),s(S>=0),s(A==null||A instanceof Uint8Array),s(A==null||A.length==_.length/M),s(R>=0&&R<=p.length),s(R%3==0),s(C>=0),s(Array.isArray(E)),s(S>=E.length),s(E.length<=32);for(var N=0;N<E.length;++N)s(E[N]>=0);for(var U=0,N=0;N<(L?L.length:0);++N)s(L[N]in v),U|=v[L[N]];var z=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),B=d(e.exports.meshopt_simplifyWithUpdate,z,p.length,_,_.length/M,M*4,x,S*4,new Float32Array(E),A,R,C,U);if(p!==z)for(var N=0;N<B[0];++N)p[N]=z[N];return B},getScale:function(p,_){return s(p instanceof Float32Array),s(p.length%_==0),s(_>=3),f(e.exports.meshopt_simplifyScale,p,p.length/_,_*4)},simplifyPoints:function(p,_,M,x,S,E){return s(p instanceof Float32Array),s(p.length%_==0),s(_>=3),s(M>=0&&M<=p.length/_),x?(s(x instanceof Float32Array),s(x.length%S==0),s(S>=3),s(p.length/_==x.length/S),m(e.exports.meshopt_simplifyPoints,p,p.length/_,_*4,x,S*4,E||0,M)):m(e.exports.meshopt_simplifyPoints,p,p.length/_,_*4,void 0,0,0,M)},simplifySloppy:function(p,_,M,x,S,E){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%M==0),s(M>=3),s(x==null||x instanceof Uint8Array),s(x==null||x.length==_.length/M),s(S>=0&&S<=p.length),s(S%3==0),s(E>=0);var A=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),R=y(e.exports.meshopt_simplifySloppy,A,p.length,_,_.length/M,M*4,x,S,E);return R[0]=p instanceof Uint32Array?R[0]:new p.constructor(R[0]),R},simplifyPrune:function(p,_,M,x){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%M==0),s(M>=3),s(x>=0);var S=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),E=g(e.exports.meshopt_simplifyPrune,S,p.length,_,_.length/M,M*4,x);return E=p instanceof Uint32Array?E:new p.constructor(E),E},remesh:function(p,_,M,x,S){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%M==0),s(M>=3),s(x>=4&&x<=256);for(var E=0,A=0;A<(S?S.length:0);++A)s(S[A]in w),E|=w[S[A]];var R=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p);return b(e.exports.meshopt_remesh,R,_,M*4,x,E)}}})();var Mw=6e4,hu=3e4;function Rg(i,t,e){let n=new Float32Array(3*e);for(let a=0;a<t.length;a++){let s=t[a];s!==4294967295&&(n[3*s]=i[3*a],n[3*s+1]=i[3*a+1],n[3*s+2]=i[3*a+2])}return n}function Sw(i,t){let e=new Uint32Array(i.buffer,i.byteOffset,i.length),[n]=Es.simplify(e,t,3,3*hu,1);return n.length>6*hu&&([n]=Es.simplifySloppy(e,t,3,null,3*hu,1)),n.length?n:null}function Cg({stage:i,surface:t,outlines:e,root:n}){let a=i.scene,s=null,r=!1,o=!1;function c(d,f){if(d.length/3<=Mw)return;let m=t.geometry();Es.ready.then(()=>{if(t.geometry()!==m||!Es.supported)return;let y=Sw(d,f);if(!y)return;let[g,b]=Es.compactMesh(y),v=new $n;v.setAttribute("position",new Le(Rg(m.getAttribute("position").array,g,b),3)),v.setIndex(new Le(y,1)),v.boundingSphere=m.boundingSphere,s=new sn(v,t.material),s.userData={remap:g,unique:b,normal:null},s.visible=!1,a.add(s),n.dataset.coarseFaces=String(y.length/3)})}function l(d){let f=t.geometry();if(!f||r===d||(r=d,e.show(d),n.dataset.turning=String(d),i.requestRender(),!s))return;let m=f.getAttribute("normal"),y=s.userData;m&&y.normal!==m&&(y.normal=m,s.geometry.setAttribute("normal",new Le(Rg(m.array,y.remap,y.unique),3))),s.visible=d,t.mesh().visible=!d}let h=Fe(i.controls,{start:()=>{o=!0},change:()=>{o&&l(!0)},end:()=>{o=!1,l(!1)}});function u(){r=!1,n.dataset.turning="false",s&&(a.remove(s),s.geometry.dispose(),s=null)}return{draw:c,clear:u,dispose(){u(),h()}}}var Ng=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),ww=globalThis[Ng]||(globalThis[Ng]=(vs(),La(_s))),{LineMaterial:to}=ww;var Pg=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Aw=globalThis[Pg]||(globalThis[Pg]=(vs(),La(_s))),{LineSegments2:du}=Aw;var Lg=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Ew=globalThis[Lg]||(globalThis[Lg]=(vs(),La(_s))),{LineSegmentsGeometry:uu}=Ew;var fu=2e3,Tw=6e3,Iw=3e4,Dg=["flipped","boundary","non_manifold"];function Ug(i,t,e){let n=new Float32Array(6*e.length);for(let a=0;a<e.length;a++){let s=e[a],r=t[s],o=t[s%3===2?s-2:s+1];for(let c=0;c<3;c++)n[6*a+c]=i[3*r+c],n[6*a+3+c]=i[3*o+c]}return n}function Og(i){let t=new Int32Array(3*i.length);for(let e=0;e<i.length;e++)for(let n=0;n<3;n++)t[3*e+n]=3*i[e]+n;return t}function Rw(i,t,e){let n=new Map;for(let a=0;a<t.length;a++)for(let s=0;s<3;s++){let r=3*t[a]+s,o=i[r],c=i[3*t[a]+(s+1)%3],l=o<c?o*e+c:c*e+o;n.set(l,n.has(l)?-1:r)}return Int32Array.from([...n.values()].filter(a=>a>=0)).sort()}function Fg(i,t){let e=i.flipped||new Int32Array(0);return{flipped:e.length>fu?Rw(i.faces,e,t):Og(e),boundary:i.boundary||new Int32Array(0),non_manifold:i.non_manifold||new Int32Array(0)}}function Bg(i){let t={flipped:new to({linewidth:2.5}),boundary:new to({linewidth:4}),non_manifold:new to({linewidth:4})},e=Object.fromEntries(Dg.map(d=>[d,new Yr])),n=new to({linewidth:4}),a={},s={},r=null;function o(d,f,m){for(let[y,g]of Object.entries(m)){if(!g.length)continue;let b=Ug(d,f,g),v=new $n;v.setAttribute("position",new Le(b,3));let w=new El(v,e[y]);if(w.renderOrder=1,w.userData.sides=g.length,s[y]=w,i.add(w),g.length>Tw)continue;let p=new uu;p.setPositions(b);let _=new du(p,t[y]);_.renderOrder=1,a[y]=_,i.add(_)}}function c(d){for(let[f,m]of Object.entries(s))a[f]&&(a[f].visible=!d),m.visible=d?m.userData.sides<=Iw:!a[f]}function l(d,f,m){h();let y=new uu;y.setPositions(Ug(d,f,Og([m]))),r=new du(y,n),r.renderOrder=3,i.add(r)}function h(){r&&(i.remove(r),r.geometry.dispose(),r=null)}function u(){for(let d of[...Object.values(a),...Object.values(s)])i.remove(d),d.geometry.dispose();a={},s={},h()}return{draw:o,show:c,showPicked:l,clearPicked:h,setColors(d,f){for(let m of Dg)t[m].color=new zn(d(m)),e[m].color=new zn(d(m));n.color=new zn(f)},setResolution(d,f){for(let m of[...Object.values(t),n])m.resolution.set(d,f)},clear:u,dispose(){u();for(let d of[...Object.values(t),...Object.values(e),n])d.dispose()}}}var Cw=[["front","front of a face (its normal points out of this side)","face"],["back","back of a face","face"],["flipped","outline: a face to flip","line"],["boundary","thick: an edge with one face (the rim of a hole)","line"],["non_manifold","thick: an edge with three faces or more","line"],["face_arrows","arrow from a face's centre: its unit normal","arrow"],["vertex_arrows","arrow from a vertex: its vertex normal","arrow"]];function kg(i,{counts:t,shown:e,colorOf:n}){i.textContent="";for(let[a,s,r]of Cw){if(r==="line"&&!t[a]||r==="arrow"&&!(t[a]&&e(a)))continue;let o=xt("li","tnm-key"),c=xt("span","tnm-swatch tnm-swatch-"+(r==="arrow"?"line":r));c.style.setProperty("--tnm-swatch",n(a)),c.setAttribute("aria-hidden","true");let l=a==="flipped"&&t.flipped>fu,h=l?` (${t[a]} faces)`:r==="line"?` (${t[a]})`:r==="arrow"?` (${t[a]} drawn)`:"";o.append(c,i.ownerDocument.createTextNode((l?"outline: the rim of each patch of faces to flip":s)+h)),i.appendChild(o)}}function zg(i,t){if(i.textContent="",i.hidden=!(t&&t.rows&&t.rows.length),i.hidden)return;i.appendChild(xt("p","tnm-pick-title",t.title||""));let e=xt("dl","tnm-pick-rows");for(let[n,a]of t.rows)e.append(xt("dt","",n),xt("dd","",a));i.appendChild(e)}var Ts=Math.pow(2,-24),eo=Symbol("SKIP_GENERATION"),Dl={strategy:0,maxDepth:40,targetLeafSize:10,useSharedArrayBuffer:!1,setBoundingBox:!0,onProgress:null,indirect:!1,verbose:!0,range:null,[eo]:!1};function he(i,t,e){return e.min.x=t[i],e.min.y=t[i+1],e.min.z=t[i+2],e.max.x=t[i+3],e.max.y=t[i+4],e.max.z=t[i+5],e}function no(i){let t=-1,e=-1/0;for(let n=0;n<3;n++){let a=i[n+3]-i[n];a>e&&(e=a,t=n)}return t}function pu(i,t,e){for(let n=0;n<3;n++){let a=t[i+2*n],s=t[i+2*n+1],r=a-s,o=a+s;r<e[n]&&(e[n]=r),o>e[n+3]&&(e[n+3]=o)}}function Ul(i){let t=i[3]-i[0],e=i[4]-i[1],n=i[5]-i[2];return 2*(t*e+e*n+n*t)}function Yt(i,t){return t[i+15]===65535}function ae(i,t){return t[i+6]}function oe(i,t){return t[i+14]}function ee(i){return i+8}function ne(i,t){let e=t[i+6];return i+e*8}function Is(i,t){return t[i+7]}function Ol(i,t,e,n,a){let s=1/0,r=1/0,o=1/0,c=-1/0,l=-1/0,h=-1/0,u=1/0,d=1/0,f=1/0,m=-1/0,y=-1/0,g=-1/0,b=i.offset||0;for(let v=(t-b)*6,w=(t+e-b)*6;v<w;v+=6){let p=i[v+0],_=i[v+1],M=p-_,x=p+_;M<s&&(s=M),x>c&&(c=x),p<u&&(u=p),p>m&&(m=p);let S=i[v+2],E=i[v+3],A=S-E,R=S+E;A<r&&(r=A),R>l&&(l=R),S<d&&(d=S),S>y&&(y=S);let C=i[v+4],L=i[v+5],N=C-L,U=C+L;N<o&&(o=N),U>h&&(h=U),C<f&&(f=C),C>g&&(g=C)}n[0]=s,n[1]=r,n[2]=o,n[3]=c,n[4]=l,n[5]=h,a[0]=u,a[1]=d,a[2]=f,a[3]=m,a[4]=y,a[5]=g}var xi=8,gu=8,mu=new Int32Array(xi),bi=new Float32Array(xi*6),Rs=new Float32Array(xi*6),Qn=new Float32Array(6),Fl=new Float32Array(6),aa=new Int32Array(gu),Hg=new Float32Array(gu*6);function Lw(i,t,e,n){for(let a=0;a<3;a++){let s=t[i+2*a],r=t[i+2*a+1],o=s-r,c=s+r;o<e[n+a]&&(e[n+a]=o),c>e[n+a+3]&&(e[n+a+3]=c)}}function Gg(i,t){let e=i[t+3]-i[t],n=i[t+4]-i[t+1],a=i[t+5]-i[t+2];return 2*(e*n+n*a+a*e)}function Wg(i,t,e,n,a,s){let r=-1,o=0;if(s===0)r=no(t),r!==-1&&(o=(t[r]+t[r+3])/2);else if(s===1)r=no(i),r!==-1&&(o=Dw(e,n,a,r));else if(s===2){let c=Ul(i),l=1.25*a,h=e.offset||0,u=(n-h)*6,d=(n+a-h)*6;for(let f=0;f<3;f++){let m=t[f],b=(t[f+3]-m)/xi;if(a<gu){for(let v=0;v<a;v++){let w=u+v*6,p=e[w+2*f],_=v;for(;_>0&&e[aa[_-1]+2*f]>p;)aa[_]=aa[_-1],_--;aa[_]=w}for(let v=0;v<3;v++)Qn[v]=1/0,Qn[v+3]=-1/0,Fl[v]=1/0,Fl[v+3]=-1/0;for(let v=a-1;v>=0;v--)pu(aa[v],e,Fl),Hg.set(Fl,v*6);for(let v=0;v<a-1;v++){pu(aa[v],e,Qn);let w=e[aa[v+1]+2*f];if(e[aa[v]+2*f]===w)continue;let p=v+1,_=a-p,M=Ul(Qn)/c,x=Gg(Hg,p*6)/c,S=1+1.25*(M*p+x*_);S<l&&(r=f,l=S,o=w)}}else{for(let p=0;p<xi;p++){mu[p]=0;for(let _=0;_<3;_++)bi[p*6+_]=1/0,bi[p*6+_+3]=-1/0}for(let p=u;p<d;p+=6){let x=~~((e[p+2*f]-m)/b);x>=xi&&(x=xi-1),mu[x]++,Lw(p,e,bi,x*6)}let v=(xi-1)*6;for(let p=0;p<6;p++)Rs[v+p]=bi[v+p];for(let p=xi-2;p>=0;p--){let _=p*6,M=_+6;for(let x=0;x<3;x++)Rs[_+x]=Math.min(bi[_+x],Rs[M+x]),Rs[_+x+3]=Math.max(bi[_+x+3],Rs[M+x+3])}let w=0;for(let p=0;p<xi-1;p++){let _=p*6,M=mu[p];if(M!==0)for(let R=0;R<3;R++)w===0?(Qn[R]=bi[_+R],Qn[R+3]=bi[_+R+3]):(Qn[R]=Math.min(Qn[R],bi[_+R]),Qn[R+3]=Math.max(Qn[R+3],bi[_+R+3]));w+=M;let x=0,S=0;w!==0&&(x=Ul(Qn)/c);let E=a-w;E!==0&&(S=Gg(Rs,_+6)/c);let A=1+1.25*(x*w+S*E);A<l&&(r=f,l=A,o=m+b+p*b)}}}}else console.warn(`BVH: Invalid build strategy value ${s} used.`);return{axis:r,pos:o}}function Dw(i,t,e,n){let a=0,s=i.offset;for(let r=t,o=t+e;r<o;r++)a+=i[(r-s)*6+n*2];return a/e}function jg(i,t,e,n,a,s){let r=n,o=n+a-1,c=s.pos,l=s.axis*2,h=e.offset||0;for(;;){for(;r<=o&&e[(r-h)*6+l]<c;)r++;for(;r<=o&&e[(o-h)*6+l]>=c;)o--;if(r<o){for(let u=0;u<t;u++){let d=i[r*t+u];i[r*t+u]=i[o*t+u],i[o*t+u]=d}for(let u=0;u<6;u++){let d=r-h,f=o-h,m=e[d*6+u];e[d*6+u]=e[f*6+u],e[f*6+u]=m}r++,o--}else return r}}var Uw=Math.pow(2,32),Cs=new Float32Array(6),Bl=new Float32Array(6);function Ow(i,t,e,n,a,s){let{maxDepth:r,verbose:o,targetLeafSize:c,_strictLeafSize:l=1/0,strategy:h,onProgress:u,useSharedArrayBuffer:d=!1}=a,f=i.primitiveBuffer,m=i.primitiveBufferStride,y=d?SharedArrayBuffer:ArrayBuffer,g=new y(32*Math.max(1,2*Math.ceil(n)-1)),b=new Float32Array(g),v=new Uint32Array(g),w=new Uint16Array(g),p=0,_=!1;return Ol(t,e,n,Cs,Bl),S(e,n,0),g.slice(0,p*32);function M(E){u&&u((E-s.offset)/s.count)}function x(E,A,R){let C=E*2;v[E+6]=A,w[C+14]=R,w[C+15]=65535,M(A+R)}function S(E,A,R){let C=p++,L=C*8;b.set(Cs,L),!_&&R>=r&&(_=!0,o&&console.warn(`BVH: Max depth of ${r} reached when generating BVH. Consider increasing maxDepth.`));let N=A>l;if(A<=c&&!N||R>=r){x(L,E,A);return}let U=Wg(Cs,Bl,t,E,A,h),z=U.axis===-1?-1:jg(f,m,t,E,A,U);if(U.axis===-1||z===E||z===E+A){if(!N){x(L,E,A);return}U.axis=Math.max(0,no(Cs)),z=E+Math.max(1,Math.floor(A/2))}v[L+7]=U.axis;let B=z-E;Ol(t,E,B,Cs,Bl),S(E,B,R+1);let K=p-C;if(K>Uw)throw new Error("MeshBVH: Cannot store relative child node offset greater than 32 bits.");v[L+6]=K;let W=A-B;Ol(t,z,W,Cs,Bl),S(z,W,R+1)}}function Xg(i,t){let e=i.getRootRanges(t.range),n=e[0],a=e[e.length-1],s={offset:n.offset,count:a.offset+a.count-n.offset},r=new Float32Array(6*s.count);r.offset=s.offset,i.computePrimitiveBounds(s.offset,s.count,r),i._roots=e.map(o=>Ow(i,r,o.offset,o.count,t,s))}var sa=class{constructor(t){this._getNewPrimitive=t,this._primitives=[]}getPrimitive(){let t=this._primitives;return t.length===0?this._getNewPrimitive():t.pop()}releasePrimitive(t){this._primitives.push(t)}};var bu=class{constructor(){this.float32Array=null,this.uint16Array=null,this.uint32Array=null;let t=[],e=null;this.setBuffer=n=>{e&&t.push(e),e=n,this.float32Array=new Float32Array(n),this.uint16Array=new Uint16Array(n),this.uint32Array=new Uint32Array(n)},this.clearBuffer=()=>{e=null,this.float32Array=null,this.uint16Array=null,this.uint32Array=null,t.length!==0&&this.setBuffer(t.pop())}}},Wt=new bu;var ra,Ps,Ns=[],kl=new sa(()=>new an);function qg(i,t,e,n,a,s){ra=kl.getPrimitive(),Ps=kl.getPrimitive(),Ns.push(ra,Ps),Wt.setBuffer(i._roots[t]);let r=xu(0,i.geometry,e,n,a,s);Wt.clearBuffer(),kl.releasePrimitive(ra),kl.releasePrimitive(Ps),Ns.pop(),Ns.pop();let o=Ns.length;return o>0&&(Ps=Ns[o-1],ra=Ns[o-2]),r}function xu(i,t,e,n,a=null,s=0,r=0){let{float32Array:o,uint16Array:c,uint32Array:l}=Wt,h=i*2;if(Yt(h,c)){let d=ae(i,l),f=oe(h,c);return he(i,o,ra),n(d,f,!1,r,s+i/8,ra)}else{let A=function(C){let{uint16Array:L,uint32Array:N}=Wt,U=C*2;for(;!Yt(U,L);)C=ee(C),U=C*2;return ae(C,N)},R=function(C){let{uint16Array:L,uint32Array:N}=Wt,U=C*2;for(;!Yt(U,L);)C=ne(C,N),U=C*2;return ae(C,N)+oe(U,L)},d=ee(i),f=ne(i,l),m=d,y=f,g,b,v,w;if(a&&(v=ra,w=Ps,he(m,o,v),he(y,o,w),g=a(v),b=a(w),b<g)){m=f,y=d;let C=g;g=b,b=C,v=w}v||(v=ra,he(m,o,v));let p=Yt(m*2,c),_=e(v,p,g,r+1,s+m/8),M;if(_===2){let C=A(m),N=R(m)-C;M=n(C,N,!0,r+1,s+m/8,v)}else M=_&&xu(m,t,e,n,a,s,r+1);if(M)return!0;w=Ps,he(y,o,w);let x=Yt(y*2,c),S=e(w,x,b,r+1,s+y/8),E;if(S===2){let C=A(y),N=R(y)-C;E=n(C,N,!0,r+1,s+y/8,w)}else E=S&&xu(y,t,e,n,a,s,r+1);return!!E}}var io=new Wt.constructor,zl=new Wt.constructor,oa=new sa(()=>new an),Ls=new an,Ds=new an,_u=new an,vu=new an,Mu=!1;function Yg(i,t,e,n){if(Mu)throw new Error("MeshBVH: Recursive calls to bvhcast not supported.");Mu=!0;let a=i._roots,s=t._roots,r,o=0,c=0,l=new qe().copy(e).invert();for(let h=0,u=a.length;h<u;h++){io.setBuffer(a[h]),c=0;let d=oa.getPrimitive();he(0,io.float32Array,d),d.applyMatrix4(l);for(let f=0,m=s.length;f<m&&(zl.setBuffer(s[f]),r=ti(0,0,e,l,n,o,c,0,0,d),zl.clearBuffer(),c+=s[f].byteLength/32,!r);f++);if(oa.releasePrimitive(d),io.clearBuffer(),o+=a[h].byteLength/32,r)break}return Mu=!1,r}function ti(i,t,e,n,a,s=0,r=0,o=0,c=0,l=null,h=!1){let u,d;h?(u=zl,d=io):(u=io,d=zl);let f=u.float32Array,m=u.uint32Array,y=u.uint16Array,g=d.float32Array,b=d.uint32Array,v=d.uint16Array,w=i*2,p=t*2,_=Yt(w,y),M=Yt(p,v),x=!1;if(M&&_)h?x=a(ae(t,b),oe(t*2,v),ae(i,m),oe(i*2,y),c,r+t/8,o,s+i/8):x=a(ae(i,m),oe(i*2,y),ae(t,b),oe(t*2,v),o,s+i/8,c,r+t/8);else if(M){let S=oa.getPrimitive();he(t,g,S),S.applyMatrix4(e);let E=ee(i),A=ne(i,m);he(E,f,Ls),he(A,f,Ds);let R=S.intersectsBox(Ls),C=S.intersectsBox(Ds);x=R&&ti(t,E,n,e,a,r,s,c,o+1,S,!h)||C&&ti(t,A,n,e,a,r,s,c,o+1,S,!h),oa.releasePrimitive(S)}else{let S=ee(t),E=ne(t,b);he(S,g,_u),he(E,g,vu);let A=l.intersectsBox(_u),R=l.intersectsBox(vu);if(A&&R)x=ti(i,S,e,n,a,s,r,o,c+1,l,h)||ti(i,E,e,n,a,s,r,o,c+1,l,h);else if(A)if(_)x=ti(i,S,e,n,a,s,r,o,c+1,l,h);else{let C=oa.getPrimitive();C.copy(_u).applyMatrix4(e);let L=ee(i),N=ne(i,m);he(L,f,Ls),he(N,f,Ds);let U=C.intersectsBox(Ls),z=C.intersectsBox(Ds);x=U&&ti(S,L,n,e,a,r,s,c,o+1,C,!h)||z&&ti(S,N,n,e,a,r,s,c,o+1,C,!h),oa.releasePrimitive(C)}else if(R)if(_)x=ti(i,E,e,n,a,s,r,o,c+1,l,h);else{let C=oa.getPrimitive();C.copy(vu).applyMatrix4(e);let L=ee(i),N=ne(i,m);he(L,f,Ls),he(N,f,Ds);let U=C.intersectsBox(Ls),z=C.intersectsBox(Ds);x=U&&ti(E,L,n,e,a,r,s,c,o+1,C,!h)||z&&ti(E,N,n,e,a,r,s,c,o+1,C,!h),oa.releasePrimitive(C)}}return x}var Vl=new class{constructor(){let i=null,t=null,e=null,n=!1;this.root=null,this.buffer=null,this.uint32Array=null,this.uint16Array=null,this.setBVH=(s,r)=>{if(n)throw new Error("BVHTraversalHelper: cannot call setBVH during an active traversal.");this.root=r,this.buffer=i=s._roots[r],this.uint16Array=e=new Uint16Array(i),this.uint32Array=t=new Uint32Array(i)},this.reset=()=>{this.root=null,this.buffer=i=null,this.uint16Array=e=null,this.uint32Array=t=null},this.getRangeStart=s=>{let r=s*2;for(;!Yt(r,e);)s=ee(s),r=s*2;return ae(s,t)},this.getRangeEnd=s=>{let r=s*2;for(;!Yt(r,e);)s=ne(s,t),r=s*2;return ae(s,t)+oe(r,e)};let a=(s,r,o)=>{let c=r*2,l=Yt(c,e);if(!s(o,l,r)&&!l){let u=ee(r),d=ne(r,t);a(s,u,o+1),a(s,d,o+1)}};this.traverseBuffer=s=>{if(n)throw new Error("BVHTraversalHelper: cannot start a traversal during an active traversal.");n=!0;try{a(s,0,0)}finally{n=!1}},this.traverse=s=>{this.traverseBuffer((r,o,c)=>{if(o){let l=c*2,h=t[c+6],u=e[l+14];return s(r,o,new Float32Array(i,c*4,6),h,u)}else{let l=Is(c,t);return s(r,o,new Float32Array(i,c*4,6),l)}})}}};var Jg=new an,Us=new Float32Array(6),Hl=class{constructor(){this._roots=null,this.primitiveBuffer=null,this.primitiveBufferStride=null}init(t){t={...Dl,...t},"maxLeafSize"in t&&(console.warn('BVH: "maxLeafSize" option has been deprecated. Use "targetLeafSize", instead.'),t={...t,targetLeafSize:t.maxLeafSize}),Xg(this,t)}getRootRanges(){throw new Error("BVH: getRootRanges() not implemented")}writePrimitiveBounds(){throw new Error("BVH: writePrimitiveBounds() not implemented")}writePrimitiveRangeBounds(t,e,n,a){let s=1/0,r=1/0,o=1/0,c=-1/0,l=-1/0,h=-1/0;for(let u=t,d=t+e;u<d;u++){this.writePrimitiveBounds(u,Us,0);let[f,m,y,g,b,v]=Us;f<s&&(s=f),g>c&&(c=g),m<r&&(r=m),b>l&&(l=b),y<o&&(o=y),v>h&&(h=v)}return n[a+0]=s,n[a+1]=r,n[a+2]=o,n[a+3]=c,n[a+4]=l,n[a+5]=h,n}computePrimitiveBounds(t,e,n){let a=n.offset||0;for(let s=t,r=t+e;s<r;s++){this.writePrimitiveBounds(s,Us,0);let[o,c,l,h,u,d]=Us,f=(o+h)/2,m=(c+u)/2,y=(l+d)/2,g=(h-o)/2,b=(u-c)/2,v=(d-l)/2,w=(s-a)*6;n[w+0]=f,n[w+1]=g+(Math.abs(f)+g)*Ts,n[w+2]=m,n[w+3]=b+(Math.abs(m)+b)*Ts,n[w+4]=y,n[w+5]=v+(Math.abs(y)+v)*Ts}return n}shiftPrimitiveOffsets(t){let e=this._indirectBuffer;if(e)for(let n=0,a=e.length;n<a;n++)e[n]+=t;else{let n=this._roots;for(let a=0;a<n.length;a++){let s=n[a],r=new Uint32Array(s),o=new Uint16Array(s),c=s.byteLength/32;for(let l=0;l<c;l++){let h=8*l,u=2*h;Yt(u,o)&&(r[h+6]+=t)}}}}traverse(t,e=0){Vl.setBVH(this,e),Vl.traverse(t),Vl.reset()}refit(){let t=this._roots;for(let e=0,n=t.length;e<n;e++){let a=t[e],s=new Uint32Array(a),r=new Uint16Array(a),o=new Float32Array(a),c=a.byteLength/32;for(let l=c-1;l>=0;l--){let h=l*8,u=h*2;if(Yt(u,r)){let f=ae(h,s),m=oe(u,r);this.writePrimitiveRangeBounds(f,m,Us,0),o.set(Us,h)}else{let f=ee(h),m=ne(h,s);for(let y=0;y<3;y++){let g=o[f+y],b=o[f+y+3],v=o[m+y],w=o[m+y+3];o[h+y]=g<v?g:v,o[h+y+3]=b>w?b:w}}}}}getBoundingBox(t){return t.makeEmpty(),this._roots.forEach(n=>{he(0,new Float32Array(n),Jg),t.union(Jg)}),t}shapecast(t){let{boundsTraverseOrder:e,intersectsBounds:n,intersectsRange:a,intersectsPrimitive:s,scratchPrimitive:r,iterate:o}=t;if(a&&s){let u=a;a=(d,f,m,y,g)=>u(d,f,m,y,g)?!0:o(d,f,this,s,m,y,r)}else a||(s?a=(u,d,f,m)=>o(u,d,this,s,f,m,r):a=(u,d,f)=>f);let c=!1,l=0,h=this._roots;for(let u=0,d=h.length;u<d;u++){let f=h[u];if(c=qg(this,u,n,a,e,l),c)break;l+=f.byteLength/32}return c}bvhcast(t,e,n){let{intersectsRanges:a}=n;return Yg(this,t,e,a)}};function Kg(){return typeof SharedArrayBuffer<"u"}function Su(i){return i.index?i.index.count:i.attributes.position.count}function ca(i){return Su(i)/3}function Bw(i,t=ArrayBuffer){return i>65535?new Uint32Array(new t(4*i)):new Uint16Array(new t(2*i))}function Zg(i,t){if(!i.index){let e=i.attributes.position.count,n=t.useSharedArrayBuffer?SharedArrayBuffer:ArrayBuffer,a=Bw(e,n);i.setIndex(new Le(a,1));for(let s=0;s<e;s++)a[s]=s}}function kw(i,t,e){let n=Su(i)/e,a=t||i.drawRange,s=a.start/e,r=(a.start+a.count)/e,o=Math.max(0,s),c=Math.min(n,r)-o;return{offset:Math.floor(o),count:Math.floor(c)}}function zw(i,t){return i.groups.map(e=>({offset:e.start/t,count:e.count/t}))}function wu(i,t,e){let n=kw(i,t,e),a=zw(i,e);if(!a.length)return[n];let s=[],r=n.offset,o=n.offset+n.count,c=Su(i)/e,l=[];for(let d of a){let{offset:f,count:m}=d,y=f,g=isFinite(m)?m:c-f,b=f+g;y<o&&b>r&&(l.push({pos:Math.max(r,y),isStart:!0}),l.push({pos:Math.min(o,b),isStart:!1}))}l.sort((d,f)=>d.pos!==f.pos?d.pos-f.pos:d.type==="end"?-1:1);let h=0,u=null;for(let d of l){let f=d.pos;h!==0&&f!==u&&s.push({offset:u,count:f-u}),h+=d.isStart?1:-1,u=f}return s}function Vw(i,t){let e=i[i.length-1],n=e.offset+e.count>2**16,a=i.reduce((l,h)=>l+h.count,0),s=n?4:2,r=t?new SharedArrayBuffer(a*s):new ArrayBuffer(a*s),o=n?new Uint32Array(r):new Uint16Array(r),c=0;for(let l=0;l<i.length;l++){let{offset:h,count:u}=i[l];for(let d=0;d<u;d++)o[c+d]=h+d;c+=u}return o}var Gl=class extends Hl{get indirect(){return!!this._indirectBuffer}get primitiveStride(){return null}get primitiveBufferStride(){return this.indirect?1:this.primitiveStride}set primitiveBufferStride(t){}get primitiveBuffer(){return this.indirect?this._indirectBuffer:this.geometry.index.array}set primitiveBuffer(t){}constructor(t,e={}){if(t.isBufferGeometry){if(t.index&&t.index.isInterleavedBufferAttribute)throw new Error("BVH: InterleavedBufferAttribute is not supported for the index attribute.")}else throw new Error("BVH: Only BufferGeometries are supported.");if(e.useSharedArrayBuffer&&!Kg())throw new Error("BVH: SharedArrayBuffer is not available.");super(),this.geometry=t,this.resolvePrimitiveIndex=e.indirect?n=>this._indirectBuffer[n]:n=>n,this.primitiveBuffer=null,this.primitiveBufferStride=null,this._indirectBuffer=null,e={...Dl,...e},e[eo]||this.init(e)}init(t){let{geometry:e,primitiveStride:n}=this;if(t.indirect){let a=wu(e,t.range,n),s=Vw(a,t.useSharedArrayBuffer);this._indirectBuffer=s}else Zg(e,t);super.init(t),!e.boundingBox&&t.setBoundingBox&&(e.boundingBox=this.getBoundingBox(new an))}getRootRanges(t){return this.indirect?[{offset:0,count:this._indirectBuffer.length}]:wu(this.geometry,t,this.primitiveStride)}raycastObject3D(){throw new Error("BVH: raycastObject3D() not implemented")}};var Nn=class{constructor(){this.min=1/0,this.max=-1/0}setFromPointsField(t,e){let n=1/0,a=-1/0;for(let s=0,r=t.length;s<r;s++){let c=t[s][e];n=c<n?c:n,a=c>a?c:a}this.min=n,this.max=a}setFromPoints(t,e){let n=1/0,a=-1/0;for(let s=0,r=e.length;s<r;s++){let o=e[s],c=t.dot(o);n=c<n?c:n,a=c>a?c:a}this.min=n,this.max=a}isSeparated(t){return this.min>t.max||t.min>this.max}};Nn.prototype.setFromBox=(function(){let i=new et;return function(e,n){let a=n.min,s=n.max,r=1/0,o=-1/0;for(let c=0;c<=1;c++)for(let l=0;l<=1;l++)for(let h=0;h<=1;h++){i.x=a.x*c+s.x*(1-c),i.y=a.y*l+s.y*(1-l),i.z=a.z*h+s.z*(1-h);let u=e.dot(i);r=Math.min(u,r),o=Math.max(u,o)}this.min=r,this.max=o}})();var Hw=(function(){let i=new et,t=new et,e=new et;return function(a,s,r){let o=a.start,c=i,l=s.start,h=t;e.subVectors(o,l),i.subVectors(a.end,a.start),t.subVectors(s.end,s.start);let u=e.dot(h),d=h.dot(c),f=h.dot(h),m=e.dot(c),g=c.dot(c)*f-d*d,b,v;g!==0?b=(u*d-m*f)/g:b=0,v=(u+b*d)/f,r.x=b,r.y=v}})(),ao=(function(){let i=new rn,t=new et,e=new et;return function(a,s,r,o){Hw(a,s,i);let c=i.x,l=i.y;if(c>=0&&c<=1&&l>=0&&l<=1){a.at(c,r),s.at(l,o);return}else if(c>=0&&c<=1){l<0?s.at(0,o):s.at(1,o),a.closestPointToPoint(o,!0,r);return}else if(l>=0&&l<=1){c<0?a.at(0,r):a.at(1,r),s.closestPointToPoint(r,!0,o);return}else{let h;c<0?h=a.start:h=a.end;let u;l<0?u=s.start:u=s.end;let d=t,f=e;if(a.closestPointToPoint(u,!0,t),s.closestPointToPoint(h,!0,e),d.distanceToSquared(u)<=f.distanceToSquared(h)){r.copy(d),o.copy(u);return}else{r.copy(h),o.copy(f);return}}}})(),$g=(function(){let i=new et,t=new et,e=new Ms,n=new Vn;return function(s,r){let{radius:o,center:c}=s,{a:l,b:h,c:u}=r;if(n.start=l,n.end=h,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o||(n.start=l,n.end=u,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o)||(n.start=h,n.end=u,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o))return!0;let y=r.getPlane(e);if(Math.abs(y.distanceToPoint(c))<=o){let b=y.projectPoint(c,t);if(r.containsPoint(b))return!0}return!1}})();var Gw=["x","y","z"],Fi=1e-15,Qg=Fi*Fi;function Hn(i){return Math.abs(i)<Fi}var Ye=class extends Oi{constructor(...t){super(...t),this.isExtendedTriangle=!0,this.satAxes=new Array(4).fill().map(()=>new et),this.satBounds=new Array(4).fill().map(()=>new Nn),this.points=[this.a,this.b,this.c],this.plane=new Ms,this.isDegenerateIntoSegment=!1,this.isDegenerateIntoPoint=!1,this.degenerateSegment=new Vn,this.needsUpdate=!0}intersectsSphere(t){return $g(t,this)}update(){let t=this.a,e=this.b,n=this.c,a=this.points,s=this.satAxes,r=this.satBounds,o=s[0],c=r[0];this.getNormal(o),c.setFromPoints(o,a);let l=s[1],h=r[1];l.subVectors(t,e),h.setFromPoints(l,a);let u=s[2],d=r[2];u.subVectors(e,n),d.setFromPoints(u,a);let f=s[3],m=r[3];f.subVectors(n,t),m.setFromPoints(f,a);let y=l.length(),g=u.length(),b=f.length();this.isDegenerateIntoPoint=!1,this.isDegenerateIntoSegment=!1,y<Fi?g<Fi||b<Fi?this.isDegenerateIntoPoint=!0:(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(t),this.degenerateSegment.end.copy(n)):g<Fi?b<Fi?this.isDegenerateIntoPoint=!0:(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(e),this.degenerateSegment.end.copy(t)):b<Fi&&(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(n),this.degenerateSegment.end.copy(e)),this.plane.setFromNormalAndCoplanarPoint(o,t),this.needsUpdate=!1}};Ye.prototype.closestPointToSegment=(function(){let i=new et,t=new et,e=new Vn;return function(a,s=null,r=null){this.needsUpdate&&this.update();let{start:o,end:c}=a,l=this.points,h,u=1/0,d=this.plane.distanceToPoint(o),f=this.plane.distanceToPoint(c);if(d*f<0&&this.plane.intersectLine(a,i)!==null&&this.containsPoint(i))return s&&s.copy(i),r&&r.copy(i),0;for(let m=0;m<3;m++){let y=(m+1)%3;e.start.copy(l[m]),e.end.copy(l[y]),ao(e,a,i,t),h=i.distanceToSquared(t),h<u&&(u=h,s&&s.copy(i),r&&r.copy(t))}return this.closestPointToPoint(o,i),h=o.distanceToSquared(i),h<u&&(u=h,s&&s.copy(i),r&&r.copy(o)),this.closestPointToPoint(c,i),h=c.distanceToSquared(i),h<u&&(u=h,s&&s.copy(i),r&&r.copy(c)),Math.sqrt(u)}})();Ye.prototype.intersectsTriangle=(function(){let i=new Ye,t=new Nn,e=new Nn,n=new et,a=new et,s=new et,r=new et,o=new Vn,c=new Vn,l=new et,h=new rn,u=new rn;function d(w,p,_,M){let x=n;!w.isDegenerateIntoPoint&&!w.isDegenerateIntoSegment?x.copy(w.plane.normal):x.copy(p.plane.normal);let S=w.satBounds,E=w.satAxes;for(let C=1;C<4;C++){let L=S[C],N=E[C];if(t.setFromPoints(N,p.points),L.isSeparated(t)||(r.copy(x).cross(N),t.setFromPoints(r,w.points),e.setFromPoints(r,p.points),t.isSeparated(e)))return!1}let A=p.satBounds,R=p.satAxes;for(let C=1;C<4;C++){let L=A[C],N=R[C];if(t.setFromPoints(N,w.points),L.isSeparated(t)||(r.crossVectors(x,N),t.setFromPoints(r,w.points),e.setFromPoints(r,p.points),t.isSeparated(e)))return!1}return _&&(M||console.warn("ExtendedTriangle.intersectsTriangle: Triangles are coplanar which does not support an output edge. Setting edge to 0, 0, 0."),_.start.set(0,0,0),_.end.set(0,0,0)),!0}function f(w,p,_,M,x,S,E,A,R,C,L){let N=E/(E-A);C.x=M+(x-M)*N,L.start.subVectors(p,w).multiplyScalar(N).add(w),N=E/(E-R),C.y=M+(S-M)*N,L.end.subVectors(_,w).multiplyScalar(N).add(w)}function m(w,p,_,M,x,S,E,A,R,C,L){if(x>0)f(w.c,w.a,w.b,M,p,_,R,E,A,C,L);else if(S>0)f(w.b,w.a,w.c,_,p,M,A,E,R,C,L);else if(A*R>0||E!=0)f(w.a,w.b,w.c,p,_,M,E,A,R,C,L);else if(A!=0)f(w.b,w.a,w.c,_,p,M,A,E,R,C,L);else if(R!=0)f(w.c,w.a,w.b,M,p,_,R,E,A,C,L);else return!0;return!1}function y(w,p,_,M){let x=p.degenerateSegment,S=w.plane.distanceToPoint(x.start),E=w.plane.distanceToPoint(x.end);return Hn(S)?Hn(E)?d(w,p,_,M):(_&&(_.start.copy(x.start),_.end.copy(x.start)),w.containsPoint(x.start)):Hn(E)?(_&&(_.start.copy(x.end),_.end.copy(x.end)),w.containsPoint(x.end)):w.plane.intersectLine(x,n)!=null?(_&&(_.start.copy(n),_.end.copy(n)),w.containsPoint(n)):!1}function g(w,p,_){let M=p.a;return Hn(w.plane.distanceToPoint(M))&&w.containsPoint(M)?(_&&(_.start.copy(M),_.end.copy(M)),!0):!1}function b(w,p,_){let M=w.degenerateSegment,x=p.a;return M.closestPointToPoint(x,!0,n),x.distanceToSquared(n)<Qg?(_&&(_.start.copy(x),_.end.copy(x)),!0):!1}function v(w,p,_,M){if(w.isDegenerateIntoSegment)if(p.isDegenerateIntoSegment){let x=w.degenerateSegment,S=p.degenerateSegment,E=a,A=s;x.delta(E),S.delta(A);let R=n.subVectors(S.start,x.start),C=E.x*A.y-E.y*A.x;if(Hn(C))return!1;let L=(R.x*A.y-R.y*A.x)/C,N=-(E.x*R.y-E.y*R.x)/C;if(L<0||L>1||N<0||N>1)return!1;let U=x.start.z+E.z*L,z=S.start.z+A.z*N;return Hn(U-z)?(_&&(_.start.copy(x.start).addScaledVector(E,L),_.end.copy(x.start).addScaledVector(E,L)),!0):!1}else return p.isDegenerateIntoPoint?b(w,p,_):y(p,w,_,M);else{if(w.isDegenerateIntoPoint)return p.isDegenerateIntoPoint?p.a.distanceToSquared(w.a)<Qg?(_&&(_.start.copy(w.a),_.end.copy(w.a)),!0):!1:p.isDegenerateIntoSegment?b(p,w,_):g(p,w,_);if(p.isDegenerateIntoPoint)return g(w,p,_);if(p.isDegenerateIntoSegment)return y(w,p,_,M)}}return function(p,_=null,M=!1){this.needsUpdate&&this.update(),p.isExtendedTriangle?p.needsUpdate&&p.update():(i.copy(p),i.update(),p=i);let x=v(this,p,_,M);if(x!==void 0)return x;let S=this.plane,E=p.plane,A=E.distanceToPoint(this.a),R=E.distanceToPoint(this.b),C=E.distanceToPoint(this.c);Hn(A)&&(A=0),Hn(R)&&(R=0),Hn(C)&&(C=0);let L=A*R,N=A*C;if(L>0&&N>0)return!1;let U=S.distanceToPoint(p.a),z=S.distanceToPoint(p.b),B=S.distanceToPoint(p.c);Hn(U)&&(U=0),Hn(z)&&(z=0),Hn(B)&&(B=0);let K=U*z,W=U*B;if(K>0&&W>0)return!1;a.copy(S.normal),s.copy(E.normal);let Y=a.cross(s),tt=0,gt=Math.abs(Y.x),It=Math.abs(Y.y);It>gt&&(gt=It,tt=1),Math.abs(Y.z)>gt&&(tt=2);let it=Gw[tt],_t=this.a[it],Et=this.b[it],pt=this.c[it],Ut=p.a[it],ye=p.b[it],Nt=p.c[it];if(m(this,_t,Et,pt,L,N,A,R,C,h,o))return d(this,p,_,M);if(m(p,Ut,ye,Nt,K,W,U,z,B,u,c))return d(this,p,_,M);if(h.y<h.x){let Jt=h.y;h.y=h.x,h.x=Jt,l.copy(o.start),o.start.copy(o.end),o.end.copy(l)}if(u.y<u.x){let Jt=u.y;u.y=u.x,u.x=Jt,l.copy(c.start),c.start.copy(c.end),c.end.copy(l)}return h.y<u.x||u.y<h.x?!1:(_&&(u.x>h.x?_.start.copy(c.start):_.start.copy(o.start),u.y<h.y?_.end.copy(c.end):_.end.copy(o.end)),!0)}})();Ye.prototype.distanceToPoint=(function(){let i=new et;return function(e){return this.closestPointToPoint(e,i),e.distanceTo(i)}})();Ye.prototype.distanceToTriangle=(function(){let i=new et,t=new et,e=["a","b","c"],n=new Vn,a=new Vn;return function(r,o=null,c=null){let l=o||c?n:null;if(this.intersectsTriangle(r,l,!0))return(o||c)&&(o&&l.getCenter(o),c&&l.getCenter(c)),0;let h=1/0;for(let u=0;u<3;u++){let d,f=e[u],m=r[f];this.closestPointToPoint(m,i),d=m.distanceToSquared(i),d<h&&(h=d,o&&o.copy(i),c&&c.copy(m));let y=this[f];r.closestPointToPoint(y,i),d=y.distanceToSquared(i),d<h&&(h=d,o&&o.copy(y),c&&c.copy(i))}for(let u=0;u<3;u++){let d=e[u],f=e[(u+1)%3];n.set(this[d],this[f]);for(let m=0;m<3;m++){let y=e[m],g=e[(m+1)%3];a.set(r[y],r[g]),ao(n,a,i,t);let b=i.distanceToSquared(t);b<h&&(h=b,o&&o.copy(i),c&&c.copy(t))}}return Math.sqrt(h)}})();var _e=class{constructor(t,e,n){this.isOrientedBox=!0,this.min=new et,this.max=new et,this.matrix=new qe,this.invMatrix=new qe,this.points=new Array(8).fill().map(()=>new et),this.satAxes=new Array(3).fill().map(()=>new et),this.satBounds=new Array(3).fill().map(()=>new Nn),this.alignedSatBounds=new Array(3).fill().map(()=>new Nn),this.needsUpdate=!1,t&&this.min.copy(t),e&&this.max.copy(e),n&&this.matrix.copy(n)}set(t,e,n){this.min.copy(t),this.max.copy(e),this.matrix.copy(n),this.needsUpdate=!0}copy(t){this.min.copy(t.min),this.max.copy(t.max),this.matrix.copy(t.matrix),this.needsUpdate=!0}};_e.prototype.update=(function(){return function(){let t=this.matrix,e=this.min,n=this.max,a=this.points;for(let l=0;l<=1;l++)for(let h=0;h<=1;h++)for(let u=0;u<=1;u++){let d=1*l|2*h|4*u,f=a[d];f.x=l?n.x:e.x,f.y=h?n.y:e.y,f.z=u?n.z:e.z,f.applyMatrix4(t)}let s=this.satBounds,r=this.satAxes,o=a[0];for(let l=0;l<3;l++){let h=r[l],u=s[l],d=1<<l,f=a[d];h.subVectors(o,f),u.setFromPoints(h,a)}let c=this.alignedSatBounds;c[0].setFromPointsField(a,"x"),c[1].setFromPointsField(a,"y"),c[2].setFromPointsField(a,"z"),this.invMatrix.copy(this.matrix).invert(),this.needsUpdate=!1}})();_e.prototype.intersectsBox=(function(){let i=new Nn;return function(e){this.needsUpdate&&this.update();let n=e.min,a=e.max,s=this.satBounds,r=this.satAxes,o=this.alignedSatBounds;if(i.min=n.x,i.max=a.x,o[0].isSeparated(i)||(i.min=n.y,i.max=a.y,o[1].isSeparated(i))||(i.min=n.z,i.max=a.z,o[2].isSeparated(i)))return!1;for(let c=0;c<3;c++){let l=r[c],h=s[c];if(i.setFromBox(l,e),h.isSeparated(i))return!1}return!0}})();_e.prototype.intersectsTriangle=(function(){let i=new Ye,t=new Array(3),e=new Nn,n=new Nn,a=new et;return function(r){this.needsUpdate&&this.update(),r.isExtendedTriangle?r.needsUpdate&&r.update():(i.copy(r),i.update(),r=i);let o=this.satBounds,c=this.satAxes;t[0]=r.a,t[1]=r.b,t[2]=r.c;for(let d=0;d<3;d++){let f=o[d],m=c[d];if(e.setFromPoints(m,t),f.isSeparated(e))return!1}let l=r.satBounds,h=r.satAxes,u=this.points;for(let d=0;d<3;d++){let f=l[d],m=h[d];if(e.setFromPoints(m,u),f.isSeparated(e))return!1}for(let d=0;d<3;d++){let f=c[d];for(let m=0;m<4;m++){let y=h[m];if(a.crossVectors(f,y),e.setFromPoints(a,t),n.setFromPoints(a,u),e.isSeparated(n))return!1}}return!0}})();_e.prototype.closestPointToPoint=(function(){return function(t,e){return this.needsUpdate&&this.update(),e.copy(t).applyMatrix4(this.invMatrix).clamp(this.min,this.max).applyMatrix4(this.matrix),e}})();_e.prototype.distanceToPoint=(function(){let i=new et;return function(e){return this.closestPointToPoint(e,i),e.distanceTo(i)}})();_e.prototype.distanceToBox=(function(){let i=["x","y","z"],t=new Array(12).fill().map(()=>new Vn),e=new Array(12).fill().map(()=>new Vn),n=new et,a=new et;return function(r,o=0,c=null,l=null){if(this.needsUpdate&&this.update(),this.intersectsBox(r))return(c||l)&&(r.getCenter(a),this.closestPointToPoint(a,n),r.closestPointToPoint(n,a),c&&c.copy(n),l&&l.copy(a)),0;let h=o*o,u=r.min,d=r.max,f=this.points,m=1/0;for(let g=0;g<8;g++){let b=f[g];a.copy(b).clamp(u,d);let v=b.distanceToSquared(a);if(v<m&&(m=v,c&&c.copy(b),l&&l.copy(a),v<h))return Math.sqrt(v)}let y=0;for(let g=0;g<3;g++)for(let b=0;b<=1;b++)for(let v=0;v<=1;v++){let w=(g+1)%3,p=(g+2)%3,_=b<<w|v<<p,M=1<<g|b<<w|v<<p,x=f[_],S=f[M];t[y].set(x,S);let A=i[g],R=i[w],C=i[p],L=e[y],N=L.start,U=L.end;N[A]=u[A],N[R]=b?u[R]:d[R],N[C]=v?u[C]:d[C],U[A]=d[A],U[R]=b?u[R]:d[R],U[C]=v?u[C]:d[C],y++}for(let g=0;g<=1;g++)for(let b=0;b<=1;b++)for(let v=0;v<=1;v++){a.x=g?d.x:u.x,a.y=b?d.y:u.y,a.z=v?d.z:u.z,this.closestPointToPoint(a,n);let w=a.distanceToSquared(n);if(w<m&&(m=w,c&&c.copy(n),l&&l.copy(a),w<h))return Math.sqrt(w)}for(let g=0;g<12;g++){let b=t[g];for(let v=0;v<12;v++){let w=e[v];ao(b,w,n,a);let p=n.distanceToSquared(a);if(p<m&&(m=p,c&&c.copy(n),l&&l.copy(a),p<h))return Math.sqrt(p)}}return Math.sqrt(m)}})();var Au=class extends sa{constructor(){super(()=>new Ye)}},xn=new Au;var so=new et,Eu=new et;function tb(i,t,e={},n=0,a=1/0){let s=n*n,r=a*a,o=1/0,c=null;if(i.shapecast({boundsTraverseOrder:h=>(so.copy(t).clamp(h.min,h.max),so.distanceToSquared(t)),intersectsBounds:(h,u,d)=>d<o&&d<r,intersectsTriangle:(h,u)=>{h.closestPointToPoint(t,so);let d=t.distanceToSquared(so);return d<o&&(Eu.copy(so),o=d,c=u),d<s}}),o===1/0)return null;let l=Math.sqrt(o);return e.point?e.point.copy(Eu):e.point=Eu.clone(),e.distance=l,e.faceIndex=c,e}var Wl=parseInt(Yd)>=169,Ww=parseInt(Yd)<=161,Ca=new et,Na=new et,Pa=new et,jl=new rn,Xl=new rn,ql=new rn,eb=new et,nb=new et,ib=new et,ro=new et;function jw(i,t,e,n,a,s,r,o){let c;if(s===wl?c=i.intersectTriangle(n,e,t,!0,a):c=i.intersectTriangle(t,e,n,s!==Ui,a),c===null)return null;let l=i.origin.distanceTo(a);return l<r||l>o?null:{distance:l,point:a.clone()}}function ab(i,t,e,n,a,s,r,o,c,l,h){Ca.fromBufferAttribute(t,s),Na.fromBufferAttribute(t,r),Pa.fromBufferAttribute(t,o);let u=jw(i,Ca,Na,Pa,ro,c,l,h);if(u){if(n){jl.fromBufferAttribute(n,s),Xl.fromBufferAttribute(n,r),ql.fromBufferAttribute(n,o),u.uv=new rn;let f=Oi.getInterpolation(ro,Ca,Na,Pa,jl,Xl,ql,u.uv);Wl||(u.uv=f)}if(a){jl.fromBufferAttribute(a,s),Xl.fromBufferAttribute(a,r),ql.fromBufferAttribute(a,o),u.uv1=new rn;let f=Oi.getInterpolation(ro,Ca,Na,Pa,jl,Xl,ql,u.uv1);Wl||(u.uv1=f),Ww&&(u.uv2=u.uv1)}if(e){eb.fromBufferAttribute(e,s),nb.fromBufferAttribute(e,r),ib.fromBufferAttribute(e,o),u.normal=new et;let f=Oi.getInterpolation(ro,Ca,Na,Pa,eb,nb,ib,u.normal);u.normal.dot(i.direction)>0&&u.normal.multiplyScalar(-1),Wl||(u.normal=f)}let d={a:s,b:r,c:o,normal:new et,materialIndex:0};if(Oi.getNormal(Ca,Na,Pa,d.normal),u.face=d,u.faceIndex=s,Wl){let f=new et;Oi.getBarycoord(ro,Ca,Na,Pa,f),u.barycoord=f}}return u}function sb(i){return i&&i.isMaterial?i.side:i}function Os(i,t,e,n,a,s,r){let o=n*3,c=o+0,l=o+1,h=o+2,{index:u,groups:d}=i;i.index&&(c=u.getX(c),l=u.getX(l),h=u.getX(h));let{position:f,normal:m,uv:y,uv1:g}=i.attributes;if(Array.isArray(t)){let b=n*3;for(let v=0,w=d.length;v<w;v++){let{start:p,count:_,materialIndex:M}=d[v];if(b>=p&&b<p+_){let x=sb(t[M]),S=ab(e,f,m,y,g,c,l,h,x,s,r);if(S)if(S.faceIndex=n,S.face.materialIndex=M,a)a.push(S);else return S}}}else{let b=sb(t),v=ab(e,f,m,y,g,c,l,h,b,s,r);if(v)if(v.faceIndex=n,v.face.materialIndex=0,a)a.push(v);else return v}return null}function de(i,t,e,n){let a=i.a,s=i.b,r=i.c,o=t,c=t+1,l=t+2;e&&(o=e.getX(o),c=e.getX(c),l=e.getX(l)),a.x=n.getX(o),a.y=n.getY(o),a.z=n.getZ(o),s.x=n.getX(c),s.y=n.getY(c),s.z=n.getZ(c),r.x=n.getX(l),r.y=n.getY(l),r.z=n.getZ(l)}function rb(i,t,e,n,a,s,r,o){let{geometry:c,_indirectBuffer:l}=i;for(let h=n,u=n+a;h<u;h++)Os(c,t,e,h,s,r,o)}function ob(i,t,e,n,a,s,r){let{geometry:o,_indirectBuffer:c}=i,l=1/0,h=null;for(let u=n,d=n+a;u<d;u++){let f;f=Os(o,t,e,u,null,s,r),f&&f.distance<l&&(h=f,l=f.distance)}return h}function cb(i,t,e,n,a,s,r){let{geometry:o}=e,{index:c}=o,l=o.attributes.position;for(let h=i,u=t+i;h<u;h++){let d;if(d=h,de(r,d*3,c,l),r.needsUpdate=!0,n(r,d,a,s))return!0}return!1}function lb(i,t=null){t&&Array.isArray(t)&&(t=new Set(t));let e=i.geometry,n=e.index?e.index.array:null,a=e.attributes.position,s,r,o,c,l=0,h=i._roots;for(let d=0,f=h.length;d<f;d++)s=h[d],r=new Uint32Array(s),o=new Uint16Array(s),c=new Float32Array(s),u(0,l),l+=s.byteLength;function u(d,f,m=!1){let y=d*2;if(Yt(y,o)){let g=ae(d,r),b=oe(y,o),v=1/0,w=1/0,p=1/0,_=-1/0,M=-1/0,x=-1/0;for(let S=3*g,E=3*(g+b);S<E;S++){let A=n[S],R=a.getX(A),C=a.getY(A),L=a.getZ(A);R<v&&(v=R),R>_&&(_=R),C<w&&(w=C),C>M&&(M=C),L<p&&(p=L),L>x&&(x=L)}return c[d+0]!==v||c[d+1]!==w||c[d+2]!==p||c[d+3]!==_||c[d+4]!==M||c[d+5]!==x?(c[d+0]=v,c[d+1]=w,c[d+2]=p,c[d+3]=_,c[d+4]=M,c[d+5]=x,!0):!1}else{let g=ee(d),b=ne(d,r),v=m,w=!1,p=!1;if(t){if(!v){let A=g/8+f/32,R=b/8+f/32;w=t.has(A),p=t.has(R),v=!w&&!p}}else w=!0,p=!0;let _=v||w,M=v||p,x=!1;_&&(x=u(g,f,v));let S=!1;M&&(S=u(b,f,v));let E=x||S;if(E)for(let A=0;A<3;A++){let R=g+A,C=b+A,L=c[R],N=c[R+3],U=c[C],z=c[C+3];c[d+A]=L<U?L:U,c[d+A+3]=N>z?N:z}return E}}}function on(i,t,e,n,a){let s,r,o,c,l,h,u=1/e.direction.x,d=1/e.direction.y,f=1/e.direction.z,m=e.origin.x,y=e.origin.y,g=e.origin.z,b=t[i],v=t[i+3],w=t[i+1],p=t[i+3+1],_=t[i+2],M=t[i+3+2];return u>=0?(s=(b-m)*u,r=(v-m)*u):(s=(v-m)*u,r=(b-m)*u),d>=0?(o=(w-y)*d,c=(p-y)*d):(o=(p-y)*d,c=(w-y)*d),s>c||o>r||((o>s||isNaN(s))&&(s=o),(c<r||isNaN(r))&&(r=c),f>=0?(l=(_-g)*f,h=(M-g)*f):(l=(M-g)*f,h=(_-g)*f),s>h||l>r)?!1:((l>s||s!==s)&&(s=l),(h<r||r!==r)&&(r=h),s<=a&&r>=n)}function hb(i,t,e,n,a,s,r,o){let{geometry:c,_indirectBuffer:l}=i;for(let h=n,u=n+a;h<u;h++){let d=l?l[h]:h;Os(c,t,e,d,s,r,o)}}function db(i,t,e,n,a,s,r){let{geometry:o,_indirectBuffer:c}=i,l=1/0,h=null;for(let u=n,d=n+a;u<d;u++){let f;f=Os(o,t,e,c?c[u]:u,null,s,r),f&&f.distance<l&&(h=f,l=f.distance)}return h}function ub(i,t,e,n,a,s,r){let{geometry:o}=e,{index:c}=o,l=o.attributes.position;for(let h=i,u=t+i;h<u;h++){let d;if(d=e.resolveTriangleIndex(h),de(r,d*3,c,l),r.needsUpdate=!0,n(r,d,a,s))return!0}return!1}function fb(i,t,e,n,a,s,r){Wt.setBuffer(i._roots[t]),on(0,Wt.float32Array,n,s,r)&&Tu(0,i,e,n,a,s,r),Wt.clearBuffer()}function Tu(i,t,e,n,a,s,r){let{float32Array:o,uint16Array:c,uint32Array:l}=Wt,h=i*2;if(Yt(h,c)){let d=ae(i,l),f=oe(h,c);rb(t,e,n,d,f,a,s,r)}else{let d=ee(i);on(d,o,n,s,r)&&Tu(d,t,e,n,a,s,r);let f=ne(i,l);on(f,o,n,s,r)&&Tu(f,t,e,n,a,s,r)}}var Xw=["x","y","z"];function pb(i,t,e,n,a,s){Wt.setBuffer(i._roots[t]);let r=null;return on(0,Wt.float32Array,n,a,s)&&(r=Iu(0,i,e,n,a,s)),Wt.clearBuffer(),r}function Iu(i,t,e,n,a,s){let{float32Array:r,uint16Array:o,uint32Array:c}=Wt,l=i*2;if(Yt(l,o)){let u=ae(i,c),d=oe(l,o);return ob(t,e,n,u,d,a,s)}else{let u=Is(i,c),d=Xw[u],m=n.direction[d]>=0,y,g;m?(y=ee(i),g=ne(i,c)):(y=ne(i,c),g=ee(i));let v=on(y,r,n,a,s)?Iu(y,t,e,n,a,s):null;if(v){let _=v.point[d];if(m?_<=r[g+u]:_>=r[g+u+3])return v}let p=on(g,r,n,a,s)?Iu(g,t,e,n,a,s):null;return v&&p?v.distance<=p.distance?v:p:v||p||null}}var Yl=new an,Fs=new Ye,Bs=new Ye,oo=new qe,mb=new _e,Jl=new _e;function gb(i,t,e,n){Wt.setBuffer(i._roots[t]);let a=Ru(0,i,e,n);return Wt.clearBuffer(),a}function Ru(i,t,e,n,a=null){let{float32Array:s,uint16Array:r,uint32Array:o}=Wt,c=i*2;if(a===null&&(e.boundingBox||e.computeBoundingBox(),mb.set(e.boundingBox.min,e.boundingBox.max,n),a=mb),Yt(c,r)){let h=t.geometry,u=h.index,d=h.attributes.position,f=e.index,m=e.attributes.position,y=ae(i,o),g=oe(c,r);if(oo.copy(n).invert(),e.boundsTree)return he(i,s,Jl),Jl.matrix.copy(oo),Jl.needsUpdate=!0,e.boundsTree.shapecast({intersectsBounds:v=>Jl.intersectsBox(v),intersectsTriangle:v=>{v.a.applyMatrix4(n),v.b.applyMatrix4(n),v.c.applyMatrix4(n),v.needsUpdate=!0;for(let w=y*3,p=(g+y)*3;w<p;w+=3)if(de(Bs,w,u,d),Bs.needsUpdate=!0,v.intersectsTriangle(Bs))return!0;return!1}});{let b=ca(e);for(let v=y*3,w=(g+y)*3;v<w;v+=3){de(Fs,v,u,d),Fs.a.applyMatrix4(oo),Fs.b.applyMatrix4(oo),Fs.c.applyMatrix4(oo),Fs.needsUpdate=!0;for(let p=0,_=b*3;p<_;p+=3)if(de(Bs,p,f,m),Bs.needsUpdate=!0,Fs.intersectsTriangle(Bs))return!0}}}else{let h=ee(i),u=ne(i,o);return he(h,s,Yl),!!(a.intersectsBox(Yl)&&Ru(h,t,e,n,a)||(he(u,s,Yl),a.intersectsBox(Yl)&&Ru(u,t,e,n,a)))}}var Kl=new qe,Cu=new _e,co=new _e,qw=new et,Yw=new et,Jw=new et,Kw=new et;function bb(i,t,e,n={},a={},s=0,r=1/0){t.boundingBox||t.computeBoundingBox(),Cu.set(t.boundingBox.min,t.boundingBox.max,e),Cu.needsUpdate=!0;let o=i.geometry,c=o.attributes.position,l=o.index,h=t.attributes.position,u=t.index,d=xn.getPrimitive(),f=xn.getPrimitive(),m=qw,y=Yw,g=null,b=null;a&&(g=Jw,b=Kw);let v=1/0,w=null,p=null;return Kl.copy(e).invert(),co.matrix.copy(Kl),i.shapecast({boundsTraverseOrder:_=>Cu.distanceToBox(_),intersectsBounds:(_,M,x)=>x<v&&x<r?(M&&(co.min.copy(_.min),co.max.copy(_.max),co.needsUpdate=!0),!0):!1,intersectsRange:(_,M)=>{if(t.boundsTree)return t.boundsTree.shapecast({boundsTraverseOrder:S=>co.distanceToBox(S),intersectsBounds:(S,E,A)=>A<v&&A<r,intersectsRange:(S,E)=>{for(let A=S,R=S+E;A<R;A++){de(f,3*A,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let C=_,L=_+M;C<L;C++){de(d,3*C,l,c),d.needsUpdate=!0;let N=d.distanceToTriangle(f,m,g);if(N<v&&(y.copy(m),b&&b.copy(g),v=N,w=C,p=A),N<s)return!0}}}});{let x=ca(t);for(let S=0,E=x;S<E;S++){de(f,3*S,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let A=_,R=_+M;A<R;A++){de(d,3*A,l,c),d.needsUpdate=!0;let C=d.distanceToTriangle(f,m,g);if(C<v&&(y.copy(m),b&&b.copy(g),v=C,w=A,p=S),C<s)return!0}}}}}),xn.releasePrimitive(d),xn.releasePrimitive(f),v===1/0?null:(n.point?n.point.copy(y):n.point=y.clone(),n.distance=v,n.faceIndex=w,a&&(a.point?a.point.copy(b):a.point=b.clone(),a.point.applyMatrix4(Kl),y.applyMatrix4(Kl),a.distance=y.sub(a.point).length(),a.faceIndex=p),n)}function xb(i,t=null){t&&Array.isArray(t)&&(t=new Set(t));let e=i.geometry,n=e.index?e.index.array:null,a=e.attributes.position,s,r,o,c,l=0,h=i._roots;for(let d=0,f=h.length;d<f;d++)s=h[d],r=new Uint32Array(s),o=new Uint16Array(s),c=new Float32Array(s),u(0,l),l+=s.byteLength;function u(d,f,m=!1){let y=d*2;if(Yt(y,o)){let g=ae(d,r),b=oe(y,o),v=1/0,w=1/0,p=1/0,_=-1/0,M=-1/0,x=-1/0;for(let S=g,E=g+b;S<E;S++){let A=3*i.resolveTriangleIndex(S);for(let R=0;R<3;R++){let C=A+R;C=n?n[C]:C;let L=a.getX(C),N=a.getY(C),U=a.getZ(C);L<v&&(v=L),L>_&&(_=L),N<w&&(w=N),N>M&&(M=N),U<p&&(p=U),U>x&&(x=U)}}return c[d+0]!==v||c[d+1]!==w||c[d+2]!==p||c[d+3]!==_||c[d+4]!==M||c[d+5]!==x?(c[d+0]=v,c[d+1]=w,c[d+2]=p,c[d+3]=_,c[d+4]=M,c[d+5]=x,!0):!1}else{let g=ee(d),b=ne(d,r),v=m,w=!1,p=!1;if(t){if(!v){let A=g/8+f/32,R=b/8+f/32;w=t.has(A),p=t.has(R),v=!w&&!p}}else w=!0,p=!0;let _=v||w,M=v||p,x=!1;_&&(x=u(g,f,v));let S=!1;M&&(S=u(b,f,v));let E=x||S;if(E)for(let A=0;A<3;A++){let R=g+A,C=b+A,L=c[R],N=c[R+3],U=c[C],z=c[C+3];c[d+A]=L<U?L:U,c[d+A+3]=N>z?N:z}return E}}}function yb(i,t,e,n,a,s,r){Wt.setBuffer(i._roots[t]),on(0,Wt.float32Array,n,s,r)&&Nu(0,i,e,n,a,s,r),Wt.clearBuffer()}function Nu(i,t,e,n,a,s,r){let{float32Array:o,uint16Array:c,uint32Array:l}=Wt,h=i*2;if(Yt(h,c)){let d=ae(i,l),f=oe(h,c);hb(t,e,n,d,f,a,s,r)}else{let d=ee(i);on(d,o,n,s,r)&&Nu(d,t,e,n,a,s,r);let f=ne(i,l);on(f,o,n,s,r)&&Nu(f,t,e,n,a,s,r)}}var Zw=["x","y","z"];function _b(i,t,e,n,a,s){Wt.setBuffer(i._roots[t]);let r=null;return on(0,Wt.float32Array,n,a,s)&&(r=Pu(0,i,e,n,a,s)),Wt.clearBuffer(),r}function Pu(i,t,e,n,a,s){let{float32Array:r,uint16Array:o,uint32Array:c}=Wt,l=i*2;if(Yt(l,o)){let u=ae(i,c),d=oe(l,o);return db(t,e,n,u,d,a,s)}else{let u=Is(i,c),d=Zw[u],m=n.direction[d]>=0,y,g;m?(y=ee(i),g=ne(i,c)):(y=ne(i,c),g=ee(i));let v=on(y,r,n,a,s)?Pu(y,t,e,n,a,s):null;if(v){let _=v.point[d];if(m?_<=r[g+u]:_>=r[g+u+3])return v}let p=on(g,r,n,a,s)?Pu(g,t,e,n,a,s):null;return v&&p?v.distance<=p.distance?v:p:v||p||null}}var Zl=new an,ks=new Ye,zs=new Ye,lo=new qe,vb=new _e,$l=new _e;function Mb(i,t,e,n){Wt.setBuffer(i._roots[t]);let a=Lu(0,i,e,n);return Wt.clearBuffer(),a}function Lu(i,t,e,n,a=null){let{float32Array:s,uint16Array:r,uint32Array:o}=Wt,c=i*2;if(a===null&&(e.boundingBox||e.computeBoundingBox(),vb.set(e.boundingBox.min,e.boundingBox.max,n),a=vb),Yt(c,r)){let h=t.geometry,u=h.index,d=h.attributes.position,f=e.index,m=e.attributes.position,y=ae(i,o),g=oe(c,r);if(lo.copy(n).invert(),e.boundsTree)return he(i,s,$l),$l.matrix.copy(lo),$l.needsUpdate=!0,e.boundsTree.shapecast({intersectsBounds:v=>$l.intersectsBox(v),intersectsTriangle:v=>{v.a.applyMatrix4(n),v.b.applyMatrix4(n),v.c.applyMatrix4(n),v.needsUpdate=!0;for(let w=y,p=g+y;w<p;w++)if(de(zs,3*t.resolveTriangleIndex(w),u,d),zs.needsUpdate=!0,v.intersectsTriangle(zs))return!0;return!1}});{let b=ca(e);for(let v=y,w=g+y;v<w;v++){let p=t.resolveTriangleIndex(v);de(ks,3*p,u,d),ks.a.applyMatrix4(lo),ks.b.applyMatrix4(lo),ks.c.applyMatrix4(lo),ks.needsUpdate=!0;for(let _=0,M=b*3;_<M;_+=3)if(de(zs,_,f,m),zs.needsUpdate=!0,ks.intersectsTriangle(zs))return!0}}}else{let h=ee(i),u=ne(i,o);return he(h,s,Zl),!!(a.intersectsBox(Zl)&&Lu(h,t,e,n,a)||(he(u,s,Zl),a.intersectsBox(Zl)&&Lu(u,t,e,n,a)))}}var Ql=new qe,Du=new _e,ho=new _e,$w=new et,Qw=new et,tA=new et,eA=new et;function Sb(i,t,e,n={},a={},s=0,r=1/0){t.boundingBox||t.computeBoundingBox(),Du.set(t.boundingBox.min,t.boundingBox.max,e),Du.needsUpdate=!0;let o=i.geometry,c=o.attributes.position,l=o.index,h=t.attributes.position,u=t.index,d=xn.getPrimitive(),f=xn.getPrimitive(),m=$w,y=Qw,g=null,b=null;a&&(g=tA,b=eA);let v=1/0,w=null,p=null;return Ql.copy(e).invert(),ho.matrix.copy(Ql),i.shapecast({boundsTraverseOrder:_=>Du.distanceToBox(_),intersectsBounds:(_,M,x)=>x<v&&x<r?(M&&(ho.min.copy(_.min),ho.max.copy(_.max),ho.needsUpdate=!0),!0):!1,intersectsRange:(_,M)=>{if(t.boundsTree){let x=t.boundsTree;return x.shapecast({boundsTraverseOrder:S=>ho.distanceToBox(S),intersectsBounds:(S,E,A)=>A<v&&A<r,intersectsRange:(S,E)=>{for(let A=S,R=S+E;A<R;A++){let C=x.resolveTriangleIndex(A);de(f,3*C,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let L=_,N=_+M;L<N;L++){let U=i.resolveTriangleIndex(L);de(d,3*U,l,c),d.needsUpdate=!0;let z=d.distanceToTriangle(f,m,g);if(z<v&&(y.copy(m),b&&b.copy(g),v=z,w=L,p=A),z<s)return!0}}}})}else{let x=ca(t);for(let S=0,E=x;S<E;S++){de(f,3*S,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let A=_,R=_+M;A<R;A++){let C=i.resolveTriangleIndex(A);de(d,3*C,l,c),d.needsUpdate=!0;let L=d.distanceToTriangle(f,m,g);if(L<v&&(y.copy(m),b&&b.copy(g),v=L,w=A,p=S),L<s)return!0}}}}}),xn.releasePrimitive(d),xn.releasePrimitive(f),v===1/0?null:(n.point?n.point.copy(y):n.point=y.clone(),n.distance=v,n.faceIndex=w,a&&(a.point?a.point.copy(b):a.point=b.clone(),a.point.applyMatrix4(Ql),y.applyMatrix4(Ql),a.distance=y.sub(a.point).length(),a.faceIndex=p),n)}function Uu(i,t,e){return i===null?null:(i.point.applyMatrix4(t.matrixWorld),i.distance=i.point.distanceTo(e.ray.origin),i.object=t,i)}var th=new _e,eh=new Fm,wb=new et,Ab=new qe,Eb=new et,Ou=["getX","getY","getZ"],nh=class i extends Gl{static serialize(t,e={}){e={cloneBuffers:!0,...e};let n=t.geometry,a=t._roots,s=t._indirectBuffer,r=n.getIndex(),o={version:1,roots:null,index:null,indirectBuffer:null};return e.cloneBuffers?(o.roots=a.map(c=>c.slice()),o.index=r?r.array.slice():null,o.indirectBuffer=s?s.slice():null):(o.roots=a,o.index=r?r.array:null,o.indirectBuffer=s),o}static deserialize(t,e,n={}){n={setIndex:!0,indirect:!!t.indirectBuffer,...n};let{index:a,roots:s,indirectBuffer:r}=t;t.version||(console.warn("MeshBVH.deserialize: Serialization format has been changed and will be fixed up. It is recommended to regenerate any stored serialized data."),c(s));let o=new i(e,{...n,[eo]:!0});if(o._roots=s,o._indirectBuffer=r||null,n.setIndex){let l=e.getIndex();if(l===null){let h=new Le(t.index,1,!1);e.setIndex(h)}else l.array!==a&&(l.array.set(a),l.needsUpdate=!0)}return o;function c(l){for(let h=0;h<l.length;h++){let u=l[h],d=new Uint32Array(u),f=new Uint16Array(u);for(let m=0,y=u.byteLength/32;m<y;m++){let g=8*m,b=2*g;Yt(b,f)||(d[g+6]=d[g+6]/8-m)}}}}get primitiveStride(){return 3}get resolveTriangleIndex(){return this.resolvePrimitiveIndex}constructor(t,e={}){e.maxLeafTris&&(console.warn('MeshBVH: "maxLeafTris" option has been deprecated. Use "targetLeafSize", instead.'),e={...e,targetLeafSize:e.maxLeafTris}),super(t,e)}shiftTriangleOffsets(t){return super.shiftPrimitiveOffsets(t)}writePrimitiveBounds(t,e,n){let a=this.geometry,s=this._indirectBuffer,r=a.attributes.position,o=a.index?a.index.array:null,l=(s?s[t]:t)*3,h=l+0,u=l+1,d=l+2;o&&(h=o[h],u=o[u],d=o[d]);for(let f=0;f<3;f++){let m=r[Ou[f]](h),y=r[Ou[f]](u),g=r[Ou[f]](d),b=m;y<b&&(b=y),g<b&&(b=g);let v=m;y>v&&(v=y),g>v&&(v=g),e[n+f]=b,e[n+f+3]=v}return e}computePrimitiveBounds(t,e,n){let a=this.geometry,s=this._indirectBuffer,r=a.attributes.position,o=a.index?a.index.array:null,c=r.normalized;if(t<0||e+t-n.offset>n.length/6)throw new Error("MeshBVH: compute triangle bounds range is invalid.");let l=r.array,h=r.offset||0,u=3;r.isInterleavedBufferAttribute&&(u=r.data.stride);let d=["getX","getY","getZ"],f=n.offset;for(let m=t,y=t+e;m<y;m++){let b=(s?s[m]:m)*3,v=(m-f)*6,w=b+0,p=b+1,_=b+2;o&&(w=o[w],p=o[p],_=o[_]),c||(w=w*u+h,p=p*u+h,_=_*u+h);for(let M=0;M<3;M++){let x,S,E;c?(x=r[d[M]](w),S=r[d[M]](p),E=r[d[M]](_)):(x=l[w+M],S=l[p+M],E=l[_+M]);let A=x;S<A&&(A=S),E<A&&(A=E);let R=x;S>R&&(R=S),E>R&&(R=E);let C=(R-A)/2,L=M*2;n[v+L+0]=A+C,n[v+L+1]=C+(Math.abs(A)+C)*Ts}}return n}raycastObject3D(t,e,n=[]){let{material:a}=t;if(a===void 0)return;Ab.copy(t.matrixWorld).invert(),eh.copy(e.ray).applyMatrix4(Ab),Eb.setFromMatrixScale(t.matrixWorld),wb.copy(eh.direction).multiply(Eb);let s=wb.length(),r=e.near/s,o=e.far/s;if(e.firstHitOnly===!0){let c=this.raycastFirst(eh,a,r,o);c=Uu(c,t,e),c&&n.push(c)}else{let c=this.raycast(eh,a,r,o);for(let l=0,h=c.length;l<h;l++){let u=Uu(c[l],t,e);u&&n.push(u)}}return n}refit(t=null){return(this.indirect?xb:lb)(this,t)}raycast(t,e=mi,n=0,a=1/0){let s=this._roots,r=[],o=this.indirect?yb:fb;for(let c=0,l=s.length;c<l;c++)o(this,c,e,t,r,n,a);return r}raycastFirst(t,e=mi,n=0,a=1/0){let s=this._roots,r=null,o=this.indirect?_b:pb;for(let c=0,l=s.length;c<l;c++){let h=o(this,c,e,t,n,a);h!=null&&(r==null||h.distance<r.distance)&&(r=h)}return r}intersectsGeometry(t,e){let n=!1,a=this._roots,s=this.indirect?Mb:gb;for(let r=0,o=a.length;r<o&&(n=s(this,r,t,e),!n);r++);return n}shapecast(t){let e=xn.getPrimitive(),n=super.shapecast({...t,intersectsPrimitive:t.intersectsTriangle,scratchPrimitive:e,iterate:this.indirect?ub:cb});return xn.releasePrimitive(e),n}bvhcast(t,e,n){let{intersectsRanges:a,intersectsTriangles:s}=n,r=xn.getPrimitive(),o=this.geometry.index,c=this.geometry.attributes.position,l=this.indirect?m=>{let y=this.resolveTriangleIndex(m);de(r,y*3,o,c)}:m=>{de(r,m*3,o,c)},h=xn.getPrimitive(),u=t.geometry.index,d=t.geometry.attributes.position,f=t.indirect?m=>{let y=t.resolveTriangleIndex(m);de(h,y*3,u,d)}:m=>{de(h,m*3,u,d)};if(s){if(!(t instanceof i))throw new Error('MeshBVH: "intersectsTriangles" callback can only be used with another MeshBVH.');let m=(y,g,b,v,w,p,_,M)=>{for(let x=b,S=b+v;x<S;x++){f(x),h.a.applyMatrix4(e),h.b.applyMatrix4(e),h.c.applyMatrix4(e),h.needsUpdate=!0;for(let E=y,A=y+g;E<A;E++)if(l(E),r.needsUpdate=!0,s(r,h,E,x,w,p,_,M))return!0}return!1};if(a){let y=a;a=function(g,b,v,w,p,_,M,x){return y(g,b,v,w,p,_,M,x)?!0:m(g,b,v,w,p,_,M,x)}}else a=m}return super.bvhcast(t,e,{intersectsRanges:a})}intersectsBox(t,e){return th.set(t.min,t.max,e),th.needsUpdate=!0,this.shapecast({intersectsBounds:n=>th.intersectsBox(n),intersectsTriangle:n=>th.intersectsTriangle(n)})}intersectsSphere(t){return this.shapecast({intersectsBounds:e=>t.intersectsBox(e),intersectsTriangle:e=>e.intersectsSphere(t)})}closestPointToGeometry(t,e,n={},a={},s=0,r=1/0){return(this.indirect?Sb:bb)(this,t,e,n,a,s,r)}closestPointToPoint(t,e={},n=0,a=1/0){return tb(this,t,e,n,a)}};var nA=4;function Tb({stage:i,surface:t,root:e,canPick:n,culled:a,frame:s,onPick:r}){let o=new Tl,c=new rn,l=null,h=null,u=null;function d(){return!l&&t.geometry()&&(l=new nh(t.geometry(),{indirect:!0,targetLeafSize:32})),l}function f(){let w=globalThis.requestIdleCallback||(M=>setTimeout(M,200)),p=globalThis.cancelIdleCallback||clearTimeout,_=w(()=>{h=null,d()},{timeout:3e3});h=()=>p(_)}function m(w,p){if(!t.mesh()||!d())return-1;let _=i.canvas.getBoundingClientRect();c.set((w-_.left)/_.width*2-1,-((p-_.top)/_.height)*2+1),o.setFromCamera(c,i.camera);let M=l.raycastFirst(o.ray,a()?mi:Ui);if(!M)return-1;let{offset:x,scale:S}=s();return e.dataset.pickPoint=M.point.toArray().map((E,A)=>E/S+x[A]).join(","),M.faceIndex}function y(w){u=w.button===0?[w.clientX,w.clientY]:null}function g(w){if(!u||Math.hypot(w.clientX-u[0],w.clientY-u[1])>nA||(u=null,!n))return;let p=m(w.clientX,w.clientY);p>=0&&r(p)}let b=Fe(i.canvas,{pointerdown:y,pointerup:g});function v(){h&&h(),l=h=null}return{schedule:f,clear:v,dispose(){v(),b()}}}function iA(){let i=new Um({side:Ui,flatShading:!0,polygonOffset:!0,polygonOffsetFactor:1,polygonOffsetUnits:1}),t={value:new zn};return i.onBeforeCompile=e=>{let n="vec4 diffuseColor = vec4( diffuse, opacity );";if(!e.fragmentShader.includes(n))throw new Error("mesh view: three.js's Lambert shader changed");e.uniforms.backDiffuse=t,e.fragmentShader=`uniform vec3 backDiffuse;
`+e.fragmentShader.replace(n,"vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );")},i.customProgramCacheKey=()=>"trinormal-two-sided",{material:i,backColor:t.value}}function Ib(i){let{material:t,backColor:e}=iA(),n=null,a=null;function s(c,l,h){return n=new $n,n.setAttribute("position",new Le(c,3)),n.setIndex(new Le(l,1)),h&&h.length===c.length&&n.setAttribute("normal",new Le(h,3)),n.computeBoundingSphere(),a=new sn(n,t),i.add(a),n}function r(c,l){let h=c?mi:Ui;l&&n&&!n.getAttribute("normal")&&n.computeVertexNormals(),(t.side!==h||t.flatShading===l)&&(t.side=h,t.flatShading=!l,t.needsUpdate=!0)}function o(){a&&i.remove(a),n&&n.dispose(),n=a=null}return{material:t,geometry:()=>n,mesh:()=>a,draw:s,shade:r,setColors(c,l){t.color=new zn(c),e.set(l)},clear:o,dispose(){o(),t.dispose()}}}var Fu={cull:!1,smooth:!1,show_face_normals:!0,show_vertex_normals:!1},aA=[["cull","Cull back faces","Hide the back of every face, as a game engine does: flipped faces vanish"],["smooth","Smooth shading","Light each face with its corners' vertex normals blended, instead of one normal per face"],["show_face_normals","Face normals","Show each face's unit normal as an arrow from its centre"],["show_vertex_normals","Vertex normals","Show the vertex normals as arrows from the vertices"]];function Rb(i,t){let e={...Fu},n=a=>i.get(a)!==void 0&&i.get(a)!==null;return{get:a=>n(a)?!!i.get(a):e[a],set(a,s){e[a]=s,n(a)?(i.set(a,s),i.save_changes()):t()}}}function Cb({flags:i,stage:t,root:e}){let n=po("tnm-toolbar","3D view of the mesh"),a={};for(let[o,c,l]of aA){let h=xt("button","tnm-button tn-text-button",c);h.type="button",h.setAttribute("aria-pressed","false"),h.title=l,h.addEventListener("click",()=>i.set(o,!i.get(o))),a[o]=h}a.show_face_normals.hidden=a.show_vertex_normals.hidden=!0;let s=xt("button","tnm-button tn-text-button","Reset view");s.type="button",s.addEventListener("click",()=>t.reset()),n.append(s,...Object.values(a));let r=Rl({root:e,stage:t,filename:"mesh.png"});return{el:n,dispose:r,update(o){for(let[c,l]of Object.entries(a))l.setAttribute("aria-pressed",String(i.get(c)));a.show_face_normals.hidden=!o.has("face"),a.show_vertex_normals.hidden=!o.has("vertex")}}}var Nb=".tnm-toolbar{display:flex;flex-wrap:wrap;gap:6px;margin:0 0 6px}.tnm-button{padding:6px 9px;min-height:34px}.tnm-face-input:focus-visible{outline:3px solid #0072B2;outline-offset:2px}.tnm-stage{position:relative;width:100%;height:380px;max-height:70vh;min-height:220px;border:1px solid var(--tn-muted);border-radius:0;overflow:hidden;touch-action:pan-y}.tnm-stage:focus-visible{outline:3px solid #0072B2;outline-offset:-3px}.tnm-touch-active .tnm-stage{touch-action:none;outline:3px solid #0072B2;outline-offset:-3px}.tnm-stage canvas{display:block;width:100%;height:100%}.tnm-legend{list-style:none;margin:6px 0 0;padding:0;display:flex;flex-wrap:wrap;gap:4px 16px;font-size:14px}.tnm-key{display:flex;align-items:center;gap:6px;margin:0}.tnm-swatch{display:inline-block;flex:none;width:18px;border:1px solid var(--tn-muted)}.tnm-swatch-face{height:14px;background:var(--tnm-swatch)}.tnm-swatch-line{height:0;border:0;border-top:4px solid var(--tnm-swatch)}.tnm-hint{font-size:14px;margin:6px 0 0;color:var(--tn-muted)}.tnm-nogl{padding:12px;border:1px solid var(--tn-muted)}.tnm-pick{margin:6px 0 0;padding:6px 10px;border:1px solid var(--tn-muted);border-radius:6px;font-size:15px}.tnm-pick-title{margin:0 0 4px;font-weight:600}.tnm-pick-rows{display:grid;grid-template-columns:max-content 1fr;gap:2px 12px;margin:0}.tnm-pick-rows dt{margin:0}.tnm-pick-rows dd{margin:0;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;overflow-wrap:anywhere}.tnm-keys{display:flex;flex-wrap:wrap;align-items:center;gap:6px;margin:6px 0 0}.tnm-keys[hidden]{display:none}.tnm-face-label{font-size:14px}.tnm-face-input{font:inherit;font-size:15px;width:8.5em;min-height:34px;padding:4px 6px;border:1px solid var(--tn-muted);border-radius:6px;background:var(--tn-bg);color:var(--tn-fg)}.tnm-button[hidden]{display:none}.tnm-root.tn-fullscreen{display:flex;flex-direction:column}.tn-fullscreen .tnm-pick{position:absolute;right:18px;bottom:70px;max-width:min(480px,45vw);background:var(--tn-bg);z-index:10}.tn-fullscreen .tnm-legend{position:absolute;left:18px;bottom:70px;z-index:10;flex-direction:column;padding:6px 10px;border-radius:6px;background:var(--tn-bg)}.tn-fullscreen .tnm-hint{display:none}";var Pb={flipped:0,boundary:0,non_manifold:0,face_arrows:0,vertex_arrows:0};function rA(i){return xt("p","tnm-hint","Drag to turn the model, scroll or pinch to zoom; on a touch screen, tap the view first, then drag; from the keyboard, Tab to the view and use the arrow keys, + and −. The side a face's normal points out of is drawn in the front colour; a face you see in the back colour from outside is wound the other way."+(i?" Click or tap a face, or type its number in the Face number box, to see its vertices, its exact normal and its area.":""))}function oA(i,t){let e=xt("div","tn-view tnm-root"),n=xt("div","tnm-stage tn-stage"),a=xt("ul","tnm-legend"),s=xt("div","tnm-pick");return s.hidden=!0,t.form.hidden=!i,e.append(n,a,t.form,s,rA(i)),{root:e,stageEl:n,legend:a,panel:s}}function Vs(i,t){return $r(i.model.get("palette")||{},t,i.dark)}function Lb(i){kg(i.legend,{counts:i.counts,shown:t=>i.flags.get(t==="face_arrows"?"show_face_normals":"show_vertex_normals"),colorOf:t=>t==="face_arrows"?Vs(i,"N"):t==="vertex_arrows"?gi(i.dark).text:Vs(i,t)})}function Bu(i){let t=gi(i.dark);i.root.classList.toggle("tn-dark",i.dark),i.stage.setBackground(t.background),i.surface.setColors(Vs(i,"front"),Vs(i,"back")),i.outlines.setColors(e=>Vs(i,e),t.line),i.arrows.setColors(Vs(i,"N"),t.text),Lb(i),i.stage.requestRender()}function ih(i){let{flags:t,current:e}=i;i.surface.shade(t.get("cull"),t.get("smooth")),i.arrows.show("face",t.get("show_face_normals")),i.arrows.show("vertex",t.get("show_vertex_normals")),i.toolbar.update(i.arrows);let n=e?e.data.faces.length/3:0;i.faceForm.form.hidden=!i.canPick||!n,i.faceForm.update(n,e&&e.data.flipped),Lb(i),i.stage.requestRender()}function Db(i){let{width:t,height:e}=i.stage.size();i.outlines.setResolution(t,e)}function cA(i){for(let t of[i.surface,i.outlines,i.arrows,i.lod,i.picking])t.clear();i.current=null,i.counts=Pb}function lA(i){cA(i);let{root:t,stage:e}=i,n=Mg(i.model);if(!n||!n.positions||!n.faces){ih(i),Ub(i);return}let{pos:a,offset:s,scale:r}=Sg(n.positions);i.surface.draw(a,n.faces,n.vertex_normals),i.picking.schedule();let o=Fg(n,a.length/3);t.dataset.flippedSides=String(o.flipped.length),i.outlines.draw(a,n.faces,o),i.outlines.show(!1),e.framePoints(Tg(a),!0,Ig(a,n.faces,o)),i.lod.draw(n.faces,a),i.arrows.draw(n,a),i.counts={flipped:n.flipped?n.flipped.length:0,boundary:o.boundary.length,non_manifold:o.non_manifold.length,face_arrows:i.arrows.count("face"),vertex_arrows:i.arrows.count("vertex")},i.current={data:n,pos:a,offset:s,scale:r},Db(i),ih(i),t.dataset.faces=String(n.faces.length/3),ku(i)}function ku(i){let{model:t,current:e,root:n}=i;i.outlines.clearPicked();let a=t.get("picked");e&&Number.isInteger(a)&&a>=0&&a<e.data.faces.length/3?(i.outlines.showPicked(e.pos,e.data.faces,a),n.dataset.picked=String(a),i.faceForm.showPicked(a)):delete n.dataset.picked,zg(i.panel,t.get("selection")),Ub(i),i.stage.requestRender()}function Ub(i){let{model:t,current:e}=i;i.description.update({about:t.get("about"),faces:e?e.data.faces.length/3:0,flipped:e?e.data.flipped:null,picked:t.get("picked"),selection:t.get("selection")})}function hA({model:i,el:t}){let e=t.ownerDocument||document,n=i.get("picked")!==void 0;Vi(e,"trinormal-mesh-style",Nb);let a=of({onPick:f,picked:()=>i.get("picked")}),{root:s,stageEl:r,legend:o,panel:c}=oA(n,a);t.appendChild(s);let l;try{l=Il(r,{onRender:()=>{},margin:Eg})}catch{return r.remove(),s.appendChild(xt("p","tnm-nogl","This browser cannot draw the 3D view (WebGL is not available). The report above does not need it.")),()=>s.remove()}let h=new Pm(16777215,1.9);h.position.set(0,0,1),l.camera.add(h),l.scene.add(new Rm(16777215,1.1),l.camera);let u={model:i,root:s,stage:l,legend:o,panel:c,faceForm:a,canPick:n,dark:ws(e),current:null,counts:Pb};u.description=Ag(r),u.flags=Rb(i,()=>ih(u)),u.surface=Ib(l.scene),u.outlines=Bg(l.scene),u.arrows=vg(l.scene),u.lod=Cg({stage:l,surface:u.surface,outlines:u.outlines,root:s});let d=()=>u.flags.get("cull");u.picking=Tb({stage:l,surface:u.surface,root:s,canPick:n,culled:d,frame:()=>u.current,onPick:f}),u.toolbar=Cb({flags:u.flags,stage:l,root:s}),s.prepend(u.toolbar.el);function f(x){i.set("picked",x),i.save_changes(),ku(u)}rf(r);let m=bo(r,l),y=Pl({root:s,stageEl:r,controls:l.controls,canvas:l.canvas,activeClass:"tnm-touch-active"}),g=new ResizeObserver(()=>{Db(u),l.requestRender()});g.observe(r);let b=Nl(x=>{u.dark=x,Bu(u)},e),v=()=>lA(u),w=()=>ih(u),p=()=>Bu(u),_=()=>ku(u),M=[["change:mesh",v],["change:revision",v],["change:palette",p],["change:picked",_],["change:selection",_],["change:about",_],...Object.keys(Fu).map(x=>["change:"+x,w])];for(let[x,S]of M)i.on(x,S);return Bu(u),v(),()=>{for(let[x,S]of M)i.off(x,S);m(),u.toolbar.dispose(),y.dispose(),g.disconnect(),b();for(let x of[u.picking,u.lod,u.surface,u.outlines,u.arrows])x.dispose();l.dispose(),u.description.dispose(),s.remove()}}var zu={render:hA};function dA(i){return(i.model.get("_view")==="mesh"?zu:lu).render(i)}var uA={render:dA};return La(fA);})();
return tnxModule})());
export default R.default;
export const explorer=R.explorer,mesh=R.mesh;
