/* trinormal 3D views (the explorer and the mesh view). Bundles three.js 0.187.0, three-mesh-bvh 0.9.17 and meshoptimizer 1.3.0 (MIT licences, see THIRD_PARTY_LICENSES.txt). Built by js/explorer/build.mjs. */
const G=globalThis.__trinormalExplorer||(globalThis.__trinormalExplorer={});
const R=G["7353abcdeae7294f"]||(G["7353abcdeae7294f"]=(()=>{var tnxModule=(()=>{var Zl=Object.defineProperty;var Hg=Object.getOwnPropertyDescriptor;var Gg=Object.getOwnPropertyNames;var Wg=Object.prototype.hasOwnProperty;var ca=(i,t,e)=>()=>{if(e)throw e[0];try{return i&&(t=i(i=0)),t}catch(n){throw e=[n],n}};var Eu=(i,t)=>{for(var e in t)Zl(i,e,{get:t[e],enumerable:!0})},jg=(i,t,e,n)=>{if(t&&typeof t=="object"||typeof t=="function")for(let a of Gg(t))!Wg.call(i,a)&&a!==e&&Zl(i,a,{get:()=>t[a],enumerable:!(n=Hg(t,a))||n.enumerable});return i};var Ra=i=>jg(Zl({},"__esModule",{value:!0}),i);function Xg(i){for(let t=i.length-1;t>=0;--t)if(i[t]>=65535)return!0;return!1}function qg(i){return ArrayBuffer.isView(i)&&!(i instanceof DataView)}function Ks(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function Gf(){let i=Ks("canvas");return i.style.display="block",i}function Zs(...i){let t="THREE."+i.shift();Ya?Ya("log",t,...i):console.log(t,...i)}function Wf(i){let t=i[0];if(typeof t=="string"&&t.startsWith("TSL:")){let e=i[1];e&&e.isStackTrace?i[0]+=" "+e.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function Dt(...i){i=Wf(i);let t="THREE."+i.shift();if(Ya)Ya("warn",t,...i);else{let e=i[0];e&&e.isStackTrace?console.warn(e.getError(t)):console.warn(t,...i)}}function Ft(...i){i=Wf(i);let t="THREE."+i.shift();if(Ya)Ya("error",t,...i);else{let e=i[0];e&&e.isStackTrace?console.error(e.getError(t)):console.error(t,...i)}}function Ws(...i){let t=i.join(" ");t in Tu||(Tu[t]=!0,Dt(...i))}function jf(i,t,e){return new Promise(function(n,a){function s(){switch(i.clientWaitSync(t,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:a();break;case i.TIMEOUT_EXPIRED:setTimeout(s,e);break;default:n()}}setTimeout(s,e)})}function Ji(){let i=Math.random()*4294967295|0,t=Math.random()*4294967295|0,e=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(tn[i&255]+tn[i>>8&255]+tn[i>>16&255]+tn[i>>24&255]+"-"+tn[t&255]+tn[t>>8&255]+"-"+tn[t>>16&15|64]+tn[t>>24&255]+"-"+tn[e&63|128]+tn[e>>8&255]+"-"+tn[e>>16&255]+tn[e>>24&255]+tn[n&255]+tn[n>>8&255]+tn[n>>16&255]+tn[n>>24&255]).toLowerCase()}function zt(i,t,e){return Math.max(t,Math.min(e,i))}function nd(i,t){return(i%t+t)%t}function Yg(i,t,e,n,a){return n+(i-t)*(a-n)/(e-t)}function Jg(i,t,e){return i!==t?(e-i)/(t-i):0}function Xs(i,t,e){return(1-e)*i+e*t}function Kg(i,t,e,n){return Xs(i,t,1-Math.exp(-e*n))}function Zg(i,t=1){return t-Math.abs(nd(i,t*2)-t)}function Qg(i,t,e){return i<=t?0:i>=e?1:(i=(i-t)/(e-t),i*i*(3-2*i))}function $g(i,t,e){return i<=t?0:i>=e?1:(i=(i-t)/(e-t),i*i*i*(i*(i*6-15)+10))}function tb(i,t){return i+Math.floor(Math.random()*(t-i+1))}function eb(i,t){return i+Math.random()*(t-i)}function nb(i){return i*(.5-Math.random())}function ib(i){i!==void 0&&(Iu=i);let t=Iu+=1831565813;return t=Math.imul(t^t>>>15,t|1),t^=t+Math.imul(t^t>>>7,t|61),((t^t>>>14)>>>0)/4294967296}function ab(i){return i*js}function sb(i){return i*Ja}function rb(i){return i>0&&Number.isInteger(i)&&2**Math.round(Math.log2(i))===i}function ob(i){return Math.pow(2,Math.ceil(Math.log(i)/Math.LN2))}function id(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function cb(i,t,e,n,a){let s=Math.cos,r=Math.sin,o=s(e/2),c=r(e/2),l=s((t+n)/2),h=r((t+n)/2),u=s((t-n)/2),d=r((t-n)/2),f=s((n-t)/2),b=r((n-t)/2);switch(a){case"XYX":i.set(o*h,c*u,c*d,o*l);break;case"YZY":i.set(c*d,o*h,c*u,o*l);break;case"ZXZ":i.set(c*u,c*d,o*h,o*l);break;case"XZX":i.set(o*h,c*b,c*f,o*l);break;case"YXY":i.set(c*f,o*h,c*b,o*l);break;case"ZYZ":i.set(c*b,c*f,o*h,o*l);break;default:Dt("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+a)}}function $c(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function ad(i,t){if(t.constructor===Float32Array)return i;let e=$c(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/e,-1)}function sd(i,t){if(t.constructor===Float32Array)return i;let e=$c(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*e)}function lb(){let i={enabled:!0,workingColorSpace:Ys,spaces:{},convert:function(a,s,r){return this.enabled===!1||s===r||!s||!r||(this.spaces[s].transfer===ue&&(a.r=wi(a.r),a.g=wi(a.g),a.b=wi(a.b)),this.spaces[s].primaries!==this.spaces[r].primaries&&(a.applyMatrix3(this.spaces[s].toXYZ),a.applyMatrix3(this.spaces[r].fromXYZ)),this.spaces[r].transfer===ue&&(a.r=ja(a.r),a.g=ja(a.g),a.b=ja(a.b))),a},workingToColorSpace:function(a,s){return this.convert(a,this.workingColorSpace,s)},colorSpaceToWorking:function(a,s){return this.convert(a,s,this.workingColorSpace)},getPrimaries:function(a){return this.spaces[a].primaries},getTransfer:function(a){return a===Pi?Js:this.spaces[a].transfer},getToneMappingMode:function(a){return this.spaces[a].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(a,s=this.workingColorSpace){return a.fromArray(this.spaces[s].luminanceCoefficients)},define:function(a){Object.assign(this.spaces,a)},_getMatrix:function(a,s,r){return a.copy(this.spaces[r].fromXYZ).multiply(this.spaces[s].toXYZ)},_getDrawingBufferColorSpace:function(a){return this.spaces[a].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(a=this.workingColorSpace){return this.spaces[a].workingColorSpaceConfig.unpackColorSpace}},t=[.64,.33,.3,.6,.15,.06],e=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[Ys]:{primaries:t,whitePoint:n,transfer:Js,toXYZ:Cu,fromXYZ:Nu,luminanceCoefficients:e,workingColorSpaceConfig:{unpackColorSpace:In},outputColorSpaceConfig:{drawingBufferColorSpace:In}},[In]:{primaries:t,whitePoint:n,transfer:ue,toXYZ:Cu,fromXYZ:Nu,luminanceCoefficients:e,outputColorSpaceConfig:{drawingBufferColorSpace:In}}}),i}function wi(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function ja(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}function th(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?Xo.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(Dt("Texture: Unable to serialize Texture."),{})}function ih(i,t,e){return e<0&&(e+=1),e>1&&(e-=1),e<1/6?i+(t-i)*6*e:e<1/2?t:e<2/3?i+(t-i)*6*(2/3-e):i}function dh(i,t,e,n,a){for(let s=0,r=i.length-3;s<=r;s+=3){ha.fromArray(i,s);let o=a.x*Math.abs(ha.x)+a.y*Math.abs(ha.y)+a.z*Math.abs(ha.z),c=t.dot(ha),l=e.dot(ha),h=n.dot(ha);if(Math.max(-Math.max(c,l,h),Math.min(c,l,h))>o)return!1}return!0}function zu(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=Ji()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}function Ab(i,t,e,n,a,s,r,o){let c;if(t.side===Xe?c=n.intersectTriangle(r,s,a,!0,o):c=n.intersectTriangle(a,s,r,t.side===oi,o),c===null)return null;vo.copy(o),vo.applyMatrix4(i.matrixWorld);let l=e.ray.origin.distanceTo(vo);return l<e.near||l>e.far?null:{distance:l,point:vo.clone(),object:i}}function Mo(i,t,e,n,a,s,r,o,c,l){i.getVertexPosition(o,bo),i.getVertexPosition(c,xo),i.getVertexPosition(l,yo);let h=Ab(i,t,e,n,bo,xo,yo,Gu);if(h){let u=new k;ii.getBarycoord(Gu,bo,xo,yo,u),a&&(h.uv=ii.getInterpolatedAttribute(a,o,c,l,u,new Ut)),s&&(h.uv1=ii.getInterpolatedAttribute(s,o,c,l,u,new Ut)),r&&(h.normal=ii.getInterpolatedAttribute(r,o,c,l,u,new k),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));let d={a:o,b:c,c:l,normal:new k,materialIndex:0};ii.getNormal(bo,xo,yo,d.normal),h.face=d,h.barycoord=u}return h}function bh(i,t){return i-t}function Tb(i,t){return i.z-t.z}function Ib(i,t){return t.z-i.z}function Lb(i,t,e=0){let n=t.itemSize;if(i.isInterleavedBufferAttribute||i.array.constructor!==t.array.constructor){let a=i.count;for(let s=0;s<a;s++)for(let r=0;r<n;r++)t.setComponent(s+e,r,i.getComponent(s,r))}else t.array.set(i.array,e*n);t.needsUpdate=!0}function ei(i,t){if(i.constructor!==t.constructor){let e=Math.min(i.length,t.length);for(let n=0;n<e;n++)t[n]=i[n]}else{let e=Math.min(i.length,t.length);t.set(new i.constructor(i.buffer,0,e))}}function To(i,t,e,n,a,s,r){let o=i.geometry.attributes.position;if(Ko.fromBufferAttribute(o,a),Zo.fromBufferAttribute(o,s),e.distanceSqToSegment(Ko,Zo,_h,Yu)>n)return;_h.applyMatrix4(i.matrixWorld);let l=t.ray.origin.distanceTo(_h);if(!(l<t.near||l>t.far))return{distance:l,point:Yu.clone().applyMatrix4(i.matrixWorld),index:r,face:null,faceIndex:null,barycoord:null,object:i}}function Qu(i,t,e,n,a,s,r){let o=Ih.distanceSqToPoint(i);if(o<e){let c=new k;Ih.closestPointToPoint(i,c),c.applyMatrix4(n);let l=a.ray.origin.distanceTo(c);if(l<a.near||l>a.far)return;s.push({distance:l,distanceToRay:Math.sqrt(o),point:c,index:t,face:null,faceIndex:null,barycoord:null,object:r})}}function $u(i,t,e){let n=`${i.x},${i.y},${i.z}-${t.x},${t.y},${t.z}`,a=`${t.x},${t.y},${t.z}-${i.x},${i.y},${i.z}`;return e.has(n)===!0||e.has(a)===!0?!1:(e.add(n),e.add(a),!0)}function Sa(i){let t={};for(let e in i){t[e]={};for(let n in i[e]){let a=i[e][n];if(tf(a))a.isRenderTargetTexture?(Dt("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),t[e][n]=null):t[e][n]=a.clone();else if(Array.isArray(a))if(tf(a[0])){let s=[];for(let r=0,o=a.length;r<o;r++)s[r]=a[r].clone();t[e][n]=s}else t[e][n]=a.slice();else t[e][n]=a}}return t}function rn(i){let t={};for(let e=0;e<i.length;e++){let n=Sa(i[e]);for(let a in n)t[a]=n[a]}return t}function tf(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function Db(i){let t=[];for(let e=0;e<i.length;e++)t.push(i[e].clone());return t}function rd(i){let t=i.getRenderTarget();return t===null?i.outputColorSpace:t.isXRRenderTarget===!0?t.texture.colorSpace:Jt.workingColorSpace}function za(i,t){return!i||i.constructor===t?i:typeof t.BYTES_PER_ELEMENT=="number"?new t(i):Array.prototype.slice.call(i)}function Co(i){return i!==void 0&&i.inTangents!==void 0&&i.outTangents!==void 0}function Yf(i,t,e,n,a){let s=1-i;return s*s*s*t+3*s*s*i*e+3*s*i*i*n+i*i*i*a}function Fb(i,t,e,n,a){let s=1-i;return 3*s*s*(e-t)+6*s*i*(n-e)+3*i*i*(a-n)}function Bb(i,t,e,n,a){let s=(i-t)/(a-t);for(let r=0;r<8;r++){let o=Yf(s,t,e,n,a)-i;if(Math.abs(o)<1e-10)break;let c=Fb(s,t,e,n,a);if(Math.abs(c)<1e-10)break;s=Math.max(0,Math.min(1,s-o/c))}return s}function ef(i,t){for(let e=0,n=i.length;e!==n;e+=2)i[e]+=t}function nf(i,t){for(let e=0,n=i.length;e!==n;e+=2)i[e]*=t}function lf(i,t){return i.distance-t.distance}function Nh(i,t,e,n){let a=!0;if(i.layers.test(t.layers)&&i.raycast(t,e)===!1&&(a=!1),a===!0&&n===!0){let s=i.children;for(let r=0,o=s.length;r<o;r++)Nh(s[r],t,e,!0)}}function ld(i,t,e,n){let a=Jb(n);switch(e){case Jh:return i*t;case Rr:return i*t/a.components*a.byteLength;case va:return i*t/a.components*a.byteLength;case li:return i*t*2/a.components*a.byteLength;case ls:return i*t*2/a.components*a.byteLength;case Kh:return i*t*3/a.components*a.byteLength;case xn:return i*t*4/a.components*a.byteLength;case hs:return i*t*4/a.components*a.byteLength;case Cr:case Nr:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case Pr:case Lr:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Sc:case Ac:return Math.max(i,16)*Math.max(t,8)/4;case Mc:case wc:return Math.max(i,8)*Math.max(t,8)/2;case Ec:case Tc:case Rc:case Cc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case Ic:case Dr:case Nc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Pc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Lc:return Math.floor((i+4)/5)*Math.floor((t+3)/4)*16;case Dc:return Math.floor((i+4)/5)*Math.floor((t+4)/5)*16;case Uc:return Math.floor((i+5)/6)*Math.floor((t+4)/5)*16;case Oc:return Math.floor((i+5)/6)*Math.floor((t+5)/6)*16;case Fc:return Math.floor((i+7)/8)*Math.floor((t+4)/5)*16;case Bc:return Math.floor((i+7)/8)*Math.floor((t+5)/6)*16;case kc:return Math.floor((i+7)/8)*Math.floor((t+7)/8)*16;case zc:return Math.floor((i+9)/10)*Math.floor((t+4)/5)*16;case Vc:return Math.floor((i+9)/10)*Math.floor((t+5)/6)*16;case Hc:return Math.floor((i+9)/10)*Math.floor((t+7)/8)*16;case Gc:return Math.floor((i+9)/10)*Math.floor((t+9)/10)*16;case Wc:return Math.floor((i+11)/12)*Math.floor((t+9)/10)*16;case jc:return Math.floor((i+11)/12)*Math.floor((t+11)/12)*16;case Xc:case qc:case Yc:return Math.ceil(i/4)*Math.ceil(t/4)*16;case Jc:case Kc:return Math.ceil(i/4)*Math.ceil(t/4)*8;case Ur:case Zc:return Math.ceil(i/4)*Math.ceil(t/4)*16}throw new Error(`Unable to determine texture byte length for ${e} format.`)}function Jb(i){switch(i){case sn:case Tr:return{byteLength:1,components:1};case Yi:case Ir:case Kn:return{byteLength:2,components:1};case _c:case vc:return{byteLength:2,components:4};case wn:case cs:case bn:return{byteLength:4,components:1};case qh:case Yh:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}var mc,qi,ri,df,Lh,uf,Ar,ff,ss,oi,Xe,Bn,ba,rs,Dh,Uh,Oh,pf,xa,mf,gf,bf,xf,yf,_f,vf,Mf,Fh,Bh,Sf,wf,Af,Ef,Tf,If,Rf,Cf,Nf,Oo,Fo,Bo,Xa,ko,zo,Vo,Ho,gc,Pf,Lf,ci,kh,zh,Vh,Hh,Gh,Wh,jh,Xh,ya,os,bc,xc,Go,ai,Wo,Pe,Df,Er,gn,yc,Ci,sn,Tr,Ir,Yi,cs,wn,bn,Kn,_c,vc,_a,qh,Yh,Jh,Kh,xn,Ei,Ni,Rr,va,li,ls,hs,Cr,Nr,Pr,Lr,Mc,Sc,wc,Ac,Ec,Tc,Ic,Rc,Cc,Dr,Nc,Pc,Lc,Dc,Uc,Oc,Fc,Bc,kc,zc,Vc,Hc,Gc,Wc,jc,Xc,qc,Yc,Jc,Kc,Ur,Zc,qs,jo,Do,Sh,wh,Ah,Eh,Uf,Qc,Of,Pi,In,Ys,Js,ue,Uo,Ff,Bf,kf,zf,Zh,Vf,Hf,Qh,$h,td,ed,On,qa,Tu,Ya,Xf,qn,tn,Iu,js,Ja,Ma,hd,Ut,Rn,dd,k,Ql,Ru,ud,Bt,$l,Cu,Nu,Jt,Ca,Xo,hb,Ka,db,eh,Sn,fd,re,qo,Cn,Qs,Yo,pc,se,Na,Wn,ub,fb,Bi,ro,En,Pu,Lu,Ti,Za,pb,Du,Pa,xi,oo,ks,mb,gb,Uu,Ou,Fu,Bu,bb,La,nh,Oe,Si,xb,Qa,qf,ki,co,Ht,en,$s,jn,yi,ah,_i,Da,Ua,ku,sh,rh,oh,ch,lh,hh,ii,Ue,vi,Xn,lo,Oa,Fa,Ba,zi,Vi,la,zs,ho,uo,ha,Ne,fo,yb,mn,tr,er,me,_b,Vs,uh,We,vb,Un,fh,ka,Tn,Hs,Ge,Le,Jo,un,Yn,ph,Mb,Sb,fn,wb,si,Mi,mh,po,mo,Jn,$a,Vu,da,go,Hu,bo,xo,yo,gh,_o,Gu,vo,an,Ai,ua,Eb,So,Ii,Wu,nr,Th,Mn,Rb,Cb,Nb,wo,fa,xh,ju,Xu,Pb,yh,nn,Ao,ir,pa,Ko,Zo,qu,Gs,Eo,_h,Yu,ma,Ju,Ku,ts,ar,Qo,Zu,Ih,Io,Ro,sr,rr,Ri,or,cr,es,ns,lr,hr,dr,ur,fr,Or,Ub,Ob,Fn,$o,pr,tc,ec,Gi,nc,ic,ac,sc,Nn,Wi,rc,oc,cc,mr,ji,lc,hc,Jf,dc,gr,vh,af,sf,uc,No,Po,ni,br,Hi,rf,of,pn,xr,Rh,yr,_r,vr,Va,Ha,is,fc,od,kb,cd,zb,Vb,Hb,Gb,Wb,jb,Xb,Ch,Ae,xS,Xi,cf,Mr,as,pd,Ph,hf,Lo,Ga,Wa,Mh,qb,Yb,ga,Sr,wr,md=ca(()=>{mc="187",qi={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},ri={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},df=0,Lh=1,uf=2,Ar=1,ff=2,ss=3,oi=0,Xe=1,Bn=2,ba=0,rs=1,Dh=2,Uh=3,Oh=4,pf=5,xa=100,mf=101,gf=102,bf=103,xf=104,yf=200,_f=201,vf=202,Mf=203,Fh=204,Bh=205,Sf=206,wf=207,Af=208,Ef=209,Tf=210,If=211,Rf=212,Cf=213,Nf=214,Oo=0,Fo=1,Bo=2,Xa=3,ko=4,zo=5,Vo=6,Ho=7,gc=0,Pf=1,Lf=2,ci=0,kh=1,zh=2,Vh=3,Hh=4,Gh=5,Wh=6,jh=7,Xh=300,ya=301,os=302,bc=303,xc=304,Go=1e3,ai=1001,Wo=1002,Pe=1003,Df=1004,Er=1005,gn=1006,yc=1007,Ci=1008,sn=1009,Tr=1010,Ir=1011,Yi=1012,cs=1013,wn=1014,bn=1015,Kn=1016,_c=1017,vc=1018,_a=1020,qh=35902,Yh=35899,Jh=1021,Kh=1022,xn=1023,Ei=1026,Ni=1027,Rr=1028,va=1029,li=1030,ls=1031,hs=1033,Cr=33776,Nr=33777,Pr=33778,Lr=33779,Mc=35840,Sc=35841,wc=35842,Ac=35843,Ec=36196,Tc=37492,Ic=37496,Rc=37488,Cc=37489,Dr=37490,Nc=37491,Pc=37808,Lc=37809,Dc=37810,Uc=37811,Oc=37812,Fc=37813,Bc=37814,kc=37815,zc=37816,Vc=37817,Hc=37818,Gc=37819,Wc=37820,jc=37821,Xc=36492,qc=36494,Yc=36495,Jc=36283,Kc=36284,Ur=36285,Zc=36286,qs=2300,jo=2301,Do=2302,Sh=2303,wh=2400,Ah=2401,Eh=2402,Uf=3200,Qc=0,Of=1,Pi="",In="srgb",Ys="srgb-linear",Js="linear",ue="srgb",Uo=7680,Ff=519,Bf=512,kf=513,zf=514,Zh=515,Vf=516,Hf=517,Qh=518,$h=519,td=35044,ed="300 es",On=2e3,qa=2001;Tu={},Ya=null;Xf={[Oo]:Oo,[Bo]:Vo,[ko]:ko,[Xa]:zo,[Fo]:Fo,[Vo]:Bo,[Ho]:Ho,[zo]:Xa},qn=class{addEventListener(t,e){this._listeners===void 0&&(this._listeners={});let n=this._listeners;n[t]===void 0&&(n[t]=[]),n[t].indexOf(e)===-1&&n[t].push(e)}hasEventListener(t,e){let n=this._listeners;return n===void 0?!1:n[t]!==void 0&&n[t].indexOf(e)!==-1}removeEventListener(t,e){let n=this._listeners;if(n===void 0)return;let a=n[t];if(a!==void 0){let s=a.indexOf(e);s!==-1&&a.splice(s,1)}}dispatchEvent(t){let e=this._listeners;if(e===void 0)return;let n=e[t.type];if(n!==void 0){t.target=this;let a=n.slice(0);for(let s=0,r=a.length;s<r;s++)a[s].call(this,t);t.target=null}}},tn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Iu=1234567,js=Math.PI/180,Ja=180/Math.PI;Ma={DEG2RAD:js,RAD2DEG:Ja,generateUUID:Ji,clamp:zt,euclideanModulo:nd,mapLinear:Yg,inverseLerp:Jg,lerp:Xs,damp:Kg,pingpong:Zg,smoothstep:Qg,smootherstep:$g,randInt:tb,randFloat:eb,randFloatSpread:nb,seededRandom:ib,degToRad:ab,radToDeg:sb,isPowerOfTwo:rb,ceilPowerOfTwo:ob,floorPowerOfTwo:id,setQuaternionFromProperEuler:cb,normalize:sd,denormalize:ad},hd=class hd{constructor(t=0,e=0){this.x=t,this.y=e}get width(){return this.x}set width(t){this.x=t}get height(){return this.y}set height(t){this.y=t}set(t,e){return this.x=t,this.y=e,this}setScalar(t){return this.x=t,this.y=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;default:throw new Error("THREE.Vector2: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y)}copy(t){return this.x=t.x,this.y=t.y,this}add(t){return this.x+=t.x,this.y+=t.y,this}addScalar(t){return this.x+=t,this.y+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this}subScalar(t){return this.x-=t,this.y-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this}multiply(t){return this.x*=t.x,this.y*=t.y,this}multiplyScalar(t){return this.x*=t,this.y*=t,this}divide(t){return this.x/=t.x,this.y/=t.y,this}divideScalar(t){return this.multiplyScalar(1/t)}applyMatrix3(t){let e=this.x,n=this.y,a=t.elements;return this.x=a[0]*e+a[3]*n+a[6],this.y=a[1]*e+a[4]*n+a[7],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this}clamp(t,e){return this.x=zt(this.x,t.x,e.x),this.y=zt(this.y,t.y,e.y),this}clampScalar(t,e){return this.x=zt(this.x,t,e),this.y=zt(this.y,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(zt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(t){return this.x*t.x+this.y*t.y}cross(t){return this.x*t.y-this.y*t.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(t){let e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;let n=this.dot(t)/e;return Math.acos(zt(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){let e=this.x-t.x,n=this.y-t.y;return e*e+n*n}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this}equals(t){return t.x===this.x&&t.y===this.y}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this}rotateAround(t,e){let n=Math.cos(e),a=Math.sin(e),s=this.x-t.x,r=this.y-t.y;return this.x=s*n-r*a+t.x,this.y=s*a+r*n+t.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};hd.prototype.isVector2=!0;Ut=hd,Rn=class{constructor(t=0,e=0,n=0,a=1){this.isQuaternion=!0,this._x=t,this._y=e,this._z=n,this._w=a}static slerpFlat(t,e,n,a,s,r,o){let c=n[a+0],l=n[a+1],h=n[a+2],u=n[a+3],d=s[r+0],f=s[r+1],b=s[r+2],_=s[r+3];if(u!==_||c!==d||l!==f||h!==b){let m=c*d+l*f+h*b+u*_;m<0&&(d=-d,f=-f,b=-b,_=-_,m=-m);let x=1-o;if(m<.9995){let v=Math.acos(m),w=Math.sin(v);x=Math.sin(x*v)/w,o=Math.sin(o*v)/w,c=c*x+d*o,l=l*x+f*o,h=h*x+b*o,u=u*x+_*o}else{c=c*x+d*o,l=l*x+f*o,h=h*x+b*o,u=u*x+_*o;let v=1/Math.sqrt(c*c+l*l+h*h+u*u);c*=v,l*=v,h*=v,u*=v}}t[e]=c,t[e+1]=l,t[e+2]=h,t[e+3]=u}static multiplyQuaternionsFlat(t,e,n,a,s,r){let o=n[a],c=n[a+1],l=n[a+2],h=n[a+3],u=s[r],d=s[r+1],f=s[r+2],b=s[r+3];return t[e]=o*b+h*u+c*f-l*d,t[e+1]=c*b+h*d+l*u-o*f,t[e+2]=l*b+h*f+o*d-c*u,t[e+3]=h*b-o*u-c*d-l*f,t}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get w(){return this._w}set w(t){this._w=t,this._onChangeCallback()}set(t,e,n,a){return this._x=t,this._y=e,this._z=n,this._w=a,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(t){return this._x=t.x,this._y=t.y,this._z=t.z,this._w=t.w,this._onChangeCallback(),this}setFromEuler(t,e=!0){let n=t._x,a=t._y,s=t._z,r=t._order,o=Math.cos,c=Math.sin,l=o(n/2),h=o(a/2),u=o(s/2),d=c(n/2),f=c(a/2),b=c(s/2);switch(r){case"XYZ":this._x=d*h*u+l*f*b,this._y=l*f*u-d*h*b,this._z=l*h*b+d*f*u,this._w=l*h*u-d*f*b;break;case"YXZ":this._x=d*h*u+l*f*b,this._y=l*f*u-d*h*b,this._z=l*h*b-d*f*u,this._w=l*h*u+d*f*b;break;case"ZXY":this._x=d*h*u-l*f*b,this._y=l*f*u+d*h*b,this._z=l*h*b+d*f*u,this._w=l*h*u-d*f*b;break;case"ZYX":this._x=d*h*u-l*f*b,this._y=l*f*u+d*h*b,this._z=l*h*b-d*f*u,this._w=l*h*u+d*f*b;break;case"YZX":this._x=d*h*u+l*f*b,this._y=l*f*u+d*h*b,this._z=l*h*b-d*f*u,this._w=l*h*u-d*f*b;break;case"XZY":this._x=d*h*u-l*f*b,this._y=l*f*u-d*h*b,this._z=l*h*b+d*f*u,this._w=l*h*u+d*f*b;break;default:Dt("Quaternion: .setFromEuler() encountered an unknown order: "+r)}return e===!0&&this._onChangeCallback(),this}setFromAxisAngle(t,e){let n=e/2,a=Math.sin(n);return this._x=t.x*a,this._y=t.y*a,this._z=t.z*a,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(t){let e=t.elements,n=e[0],a=e[4],s=e[8],r=e[1],o=e[5],c=e[9],l=e[2],h=e[6],u=e[10],d=n+o+u;if(d>0){let f=.5/Math.sqrt(d+1);this._w=.25/f,this._x=(h-c)*f,this._y=(s-l)*f,this._z=(r-a)*f}else if(n>o&&n>u){let f=2*Math.sqrt(1+n-o-u);this._w=(h-c)/f,this._x=.25*f,this._y=(a+r)/f,this._z=(s+l)/f}else if(o>u){let f=2*Math.sqrt(1+o-n-u);this._w=(s-l)/f,this._x=(a+r)/f,this._y=.25*f,this._z=(c+h)/f}else{let f=2*Math.sqrt(1+u-n-o);this._w=(r-a)/f,this._x=(s+l)/f,this._y=(c+h)/f,this._z=.25*f}return this._onChangeCallback(),this}setFromUnitVectors(t,e){let n=t.dot(e)+1;return n<1e-8?(n=0,Math.abs(t.x)>Math.abs(t.z)?(this._x=-t.y,this._y=t.x,this._z=0,this._w=n):(this._x=0,this._y=-t.z,this._z=t.y,this._w=n)):(this._x=t.y*e.z-t.z*e.y,this._y=t.z*e.x-t.x*e.z,this._z=t.x*e.y-t.y*e.x,this._w=n),this.normalize()}angleTo(t){return 2*Math.acos(Math.abs(zt(this.dot(t),-1,1)))}rotateTowards(t,e){let n=this.angleTo(t);if(n===0)return this;let a=Math.min(1,e/n);return this.slerp(t,a),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(t){return this._x*t._x+this._y*t._y+this._z*t._z+this._w*t._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let t=this.length();return t===0?(this._x=0,this._y=0,this._z=0,this._w=1):(t=1/t,this._x=this._x*t,this._y=this._y*t,this._z=this._z*t,this._w=this._w*t),this._onChangeCallback(),this}multiply(t){return this.multiplyQuaternions(this,t)}premultiply(t){return this.multiplyQuaternions(t,this)}multiplyQuaternions(t,e){let n=t._x,a=t._y,s=t._z,r=t._w,o=e._x,c=e._y,l=e._z,h=e._w;return this._x=n*h+r*o+a*l-s*c,this._y=a*h+r*c+s*o-n*l,this._z=s*h+r*l+n*c-a*o,this._w=r*h-n*o-a*c-s*l,this._onChangeCallback(),this}slerp(t,e){let n=t._x,a=t._y,s=t._z,r=t._w,o=this.dot(t);o<0&&(n=-n,a=-a,s=-s,r=-r,o=-o);let c=1-e;if(o<.9995){let l=Math.acos(o),h=Math.sin(l);c=Math.sin(c*l)/h,e=Math.sin(e*l)/h,this._x=this._x*c+n*e,this._y=this._y*c+a*e,this._z=this._z*c+s*e,this._w=this._w*c+r*e,this._onChangeCallback()}else this._x=this._x*c+n*e,this._y=this._y*c+a*e,this._z=this._z*c+s*e,this._w=this._w*c+r*e,this.normalize();return this}slerpQuaternions(t,e,n){return this.copy(t).slerp(e,n)}random(){let t=2*Math.PI*Math.random(),e=2*Math.PI*Math.random(),n=Math.random(),a=Math.sqrt(1-n),s=Math.sqrt(n);return this.set(a*Math.sin(t),a*Math.cos(t),s*Math.sin(e),s*Math.cos(e))}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._w===this._w}fromArray(t,e=0){return this._x=t[e],this._y=t[e+1],this._z=t[e+2],this._w=t[e+3],this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._w,t}fromBufferAttribute(t,e){return this._x=t.getX(e),this._y=t.getY(e),this._z=t.getZ(e),this._w=t.getW(e),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},dd=class dd{constructor(t=0,e=0,n=0){this.x=t,this.y=e,this.z=n}set(t,e,n){return n===void 0&&(n=this.z),this.x=t,this.y=e,this.z=n,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;default:throw new Error("THREE.Vector3: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this}multiplyVectors(t,e){return this.x=t.x*e.x,this.y=t.y*e.y,this.z=t.z*e.z,this}applyEuler(t){return this.applyQuaternion(Ru.setFromEuler(t))}applyAxisAngle(t,e){return this.applyQuaternion(Ru.setFromAxisAngle(t,e))}applyMatrix3(t){let e=this.x,n=this.y,a=this.z,s=t.elements;return this.x=s[0]*e+s[3]*n+s[6]*a,this.y=s[1]*e+s[4]*n+s[7]*a,this.z=s[2]*e+s[5]*n+s[8]*a,this}applyNormalMatrix(t){return this.applyMatrix3(t).normalize()}applyMatrix4(t){let e=this.x,n=this.y,a=this.z,s=t.elements,r=1/(s[3]*e+s[7]*n+s[11]*a+s[15]);return this.x=(s[0]*e+s[4]*n+s[8]*a+s[12])*r,this.y=(s[1]*e+s[5]*n+s[9]*a+s[13])*r,this.z=(s[2]*e+s[6]*n+s[10]*a+s[14])*r,this}applyQuaternion(t){let e=this.x,n=this.y,a=this.z,s=t.x,r=t.y,o=t.z,c=t.w,l=2*(r*a-o*n),h=2*(o*e-s*a),u=2*(s*n-r*e);return this.x=e+c*l+r*u-o*h,this.y=n+c*h+o*l-s*u,this.z=a+c*u+s*h-r*l,this}project(t){return this.applyMatrix4(t.matrixWorldInverse).applyMatrix4(t.projectionMatrix)}unproject(t){return this.applyMatrix4(t.projectionMatrixInverse).applyMatrix4(t.matrixWorld)}transformDirection(t){let e=this.x,n=this.y,a=this.z,s=t.elements;return this.x=s[0]*e+s[4]*n+s[8]*a,this.y=s[1]*e+s[5]*n+s[9]*a,this.z=s[2]*e+s[6]*n+s[10]*a,this.normalize()}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this}divideScalar(t){return this.multiplyScalar(1/t)}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this}clamp(t,e){return this.x=zt(this.x,t.x,e.x),this.y=zt(this.y,t.y,e.y),this.z=zt(this.z,t.z,e.z),this}clampScalar(t,e){return this.x=zt(this.x,t,e),this.y=zt(this.y,t,e),this.z=zt(this.z,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(zt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this}cross(t){return this.crossVectors(this,t)}crossVectors(t,e){let n=t.x,a=t.y,s=t.z,r=e.x,o=e.y,c=e.z;return this.x=a*c-s*o,this.y=s*r-n*c,this.z=n*o-a*r,this}projectOnVector(t){let e=t.lengthSq();if(e===0)return this.set(0,0,0);let n=t.dot(this)/e;return this.copy(t).multiplyScalar(n)}projectOnPlane(t){return Ql.copy(this).projectOnVector(t),this.sub(Ql)}reflect(t){return this.sub(Ql.copy(t).multiplyScalar(2*this.dot(t)))}angleTo(t){let e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;let n=this.dot(t)/e;return Math.acos(zt(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){let e=this.x-t.x,n=this.y-t.y,a=this.z-t.z;return e*e+n*n+a*a}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)+Math.abs(this.z-t.z)}setFromSpherical(t){return this.setFromSphericalCoords(t.radius,t.phi,t.theta)}setFromSphericalCoords(t,e,n){let a=Math.sin(e)*t;return this.x=a*Math.sin(n),this.y=Math.cos(e)*t,this.z=a*Math.cos(n),this}setFromCylindrical(t){return this.setFromCylindricalCoords(t.radius,t.theta,t.y)}setFromCylindricalCoords(t,e,n){return this.x=t*Math.sin(e),this.y=n,this.z=t*Math.cos(e),this}setFromMatrixPosition(t){let e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this}setFromMatrixScale(t){let e=this.setFromMatrixColumn(t,0).length(),n=this.setFromMatrixColumn(t,1).length(),a=this.setFromMatrixColumn(t,2).length();return this.x=e,this.y=n,this.z=a,this}setFromMatrixColumn(t,e){return this.fromArray(t.elements,e*4)}setFromMatrix3Column(t,e){return this.fromArray(t.elements,e*3)}setFromEuler(t){return this.x=t._x,this.y=t._y,this.z=t._z,this}setFromColor(t){return this.x=t.r,this.y=t.g,this.z=t.b,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let t=Math.random()*Math.PI*2,e=Math.random()*2-1,n=Math.sqrt(1-e*e);return this.x=n*Math.cos(t),this.y=e,this.z=n*Math.sin(t),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};dd.prototype.isVector3=!0;k=dd,Ql=new k,Ru=new Rn,ud=class ud{constructor(t,e,n,a,s,r,o,c,l){this.elements=[1,0,0,0,1,0,0,0,1],t!==void 0&&this.set(t,e,n,a,s,r,o,c,l)}set(t,e,n,a,s,r,o,c,l){let h=this.elements;return h[0]=t,h[1]=a,h[2]=o,h[3]=e,h[4]=s,h[5]=c,h[6]=n,h[7]=r,h[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(t){let e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],this}extractBasis(t,e,n){return t.setFromMatrix3Column(this,0),e.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(t){let e=t.elements;return this.set(e[0],e[4],e[8],e[1],e[5],e[9],e[2],e[6],e[10]),this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){let n=t.elements,a=e.elements,s=this.elements,r=n[0],o=n[3],c=n[6],l=n[1],h=n[4],u=n[7],d=n[2],f=n[5],b=n[8],_=a[0],m=a[3],x=a[6],v=a[1],w=a[4],p=a[7],y=a[2],S=a[5],g=a[8];return s[0]=r*_+o*v+c*y,s[3]=r*m+o*w+c*S,s[6]=r*x+o*p+c*g,s[1]=l*_+h*v+u*y,s[4]=l*m+h*w+u*S,s[7]=l*x+h*p+u*g,s[2]=d*_+f*v+b*y,s[5]=d*m+f*w+b*S,s[8]=d*x+f*p+b*g,this}multiplyScalar(t){let e=this.elements;return e[0]*=t,e[3]*=t,e[6]*=t,e[1]*=t,e[4]*=t,e[7]*=t,e[2]*=t,e[5]*=t,e[8]*=t,this}determinant(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8];return e*r*h-e*o*l-n*s*h+n*o*c+a*s*l-a*r*c}invert(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8],u=h*r-o*l,d=o*c-h*s,f=l*s-r*c,b=e*u+n*d+a*f;if(b===0)return this.set(0,0,0,0,0,0,0,0,0);let _=1/b;return t[0]=u*_,t[1]=(a*l-h*n)*_,t[2]=(o*n-a*r)*_,t[3]=d*_,t[4]=(h*e-a*c)*_,t[5]=(a*s-o*e)*_,t[6]=f*_,t[7]=(n*c-l*e)*_,t[8]=(r*e-n*s)*_,this}transpose(){let t,e=this.elements;return t=e[1],e[1]=e[3],e[3]=t,t=e[2],e[2]=e[6],e[6]=t,t=e[5],e[5]=e[7],e[7]=t,this}getNormalMatrix(t){return this.setFromMatrix4(t).invert().transpose()}transposeIntoArray(t){let e=this.elements;return t[0]=e[0],t[1]=e[3],t[2]=e[6],t[3]=e[1],t[4]=e[4],t[5]=e[7],t[6]=e[2],t[7]=e[5],t[8]=e[8],this}setUvTransform(t,e,n,a,s,r,o){let c=Math.cos(s),l=Math.sin(s);return this.set(n*c,n*l,-n*(c*r+l*o)+r+t,-a*l,a*c,-a*(-l*r+c*o)+o+e,0,0,1),this}scale(t,e){return Ws("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply($l.makeScale(t,e)),this}rotate(t){return Ws("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply($l.makeRotation(-t)),this}translate(t,e){return Ws("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply($l.makeTranslation(t,e)),this}makeTranslation(t,e){return t.isVector2?this.set(1,0,t.x,0,1,t.y,0,0,1):this.set(1,0,t,0,1,e,0,0,1),this}makeRotation(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,n,e,0,0,0,1),this}makeScale(t,e){return this.set(t,0,0,0,e,0,0,0,1),this}equals(t){let e=this.elements,n=t.elements;for(let a=0;a<9;a++)if(e[a]!==n[a])return!1;return!0}fromArray(t,e=0){for(let n=0;n<9;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){let n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t}clone(){return new this.constructor().fromArray(this.elements)}};ud.prototype.isMatrix3=!0;Bt=ud,$l=new Bt,Cu=new Bt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Nu=new Bt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);Jt=lb();Xo=class{static getDataURL(t,e="image/png"){if(/^data:/i.test(t.src)||typeof HTMLCanvasElement>"u")return t.src;let n;if(t instanceof HTMLCanvasElement)n=t;else{Ca===void 0&&(Ca=Ks("canvas")),Ca.width=t.width,Ca.height=t.height;let a=Ca.getContext("2d");t instanceof ImageData?a.putImageData(t,0,0):a.drawImage(t,0,0,t.width,t.height),n=Ca}return n.toDataURL(e)}static sRGBToLinear(t){if(typeof HTMLImageElement<"u"&&t instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&t instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&t instanceof ImageBitmap){let e=Ks("canvas");e.width=t.width,e.height=t.height;let n=e.getContext("2d");n.drawImage(t,0,0,t.width,t.height);let a=n.getImageData(0,0,t.width,t.height),s=a.data;for(let r=0;r<s.length;r++)s[r]=wi(s[r]/255)*255;return n.putImageData(a,0,0),e}else if(t.data){let e=t.data.slice(0);for(let n=0;n<e.length;n++)e instanceof Uint8Array||e instanceof Uint8ClampedArray?e[n]=Math.floor(wi(e[n]/255)*255):e[n]=wi(e[n]);return{data:e,width:t.width,height:t.height}}else return Dt("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),t}},hb=0,Ka=class{constructor(t=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:hb++}),this.uuid=Ji(),this.data=t,this.dataReady=!0,this.version=0}getSize(t){let e=this.data;return typeof HTMLVideoElement<"u"&&e instanceof HTMLVideoElement?t.set(e.videoWidth,e.videoHeight,0):typeof VideoFrame<"u"&&e instanceof VideoFrame?t.set(e.displayWidth,e.displayHeight,0):e!==null?t.set(e.width||0,e.height||0,e.depth||0):t.set(0,0,0),t}set needsUpdate(t){t===!0&&this.version++}toJSON(t){let e=t===void 0||typeof t=="string";if(!e&&t.images[this.uuid]!==void 0)return t.images[this.uuid];let n={uuid:this.uuid,url:""},a=this.data;if(a!==null){let s;if(Array.isArray(a)){s=[];for(let r=0,o=a.length;r<o;r++)a[r].isDataTexture?s.push(th(a[r].image)):s.push(th(a[r]))}else s=th(a);n.url=s}return e||(t.images[this.uuid]=n),n}};db=0,eh=new k,Sn=class i extends qn{constructor(t=i.DEFAULT_IMAGE,e=i.DEFAULT_MAPPING,n=ai,a=ai,s=gn,r=Ci,o=xn,c=sn,l=i.DEFAULT_ANISOTROPY,h=Pi){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:db++}),this.uuid=Ji(),this.name="",this.source=new Ka(t),this.mipmaps=[],this.mapping=e,this.channel=0,this.wrapS=n,this.wrapT=a,this.magFilter=s,this.minFilter=r,this.anisotropy=l,this.format=o,this.internalFormat=null,this.type=c,this.offset=new Ut(0,0),this.repeat=new Ut(1,1),this.center=new Ut(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new Bt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(t&&t.depth&&t.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(eh).x}get height(){return this.source.getSize(eh).y}get depth(){return this.source.getSize(eh).z}get image(){return this.source.data}set image(t){this.source.data=t}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(t){return this.name=t.name,this.source=t.source,this.mipmaps=t.mipmaps.slice(0),this.mapping=t.mapping,this.channel=t.channel,this.wrapS=t.wrapS,this.wrapT=t.wrapT,this.magFilter=t.magFilter,this.minFilter=t.minFilter,this.anisotropy=t.anisotropy,this.format=t.format,this.internalFormat=t.internalFormat,this.type=t.type,this.normalized=t.normalized,this.offset.copy(t.offset),this.repeat.copy(t.repeat),this.center.copy(t.center),this.rotation=t.rotation,this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrix.copy(t.matrix),this.generateMipmaps=t.generateMipmaps,this.mipmapsAutoUpdate=t.mipmapsAutoUpdate,this.premultiplyAlpha=t.premultiplyAlpha,this.flipY=t.flipY,this.unpackAlignment=t.unpackAlignment,this.colorSpace=t.colorSpace,this.renderTarget=t.renderTarget,this.isRenderTargetTexture=t.isRenderTargetTexture,this.isPMREMTexture=t.isPMREMTexture,this.isArrayTexture=t.isArrayTexture,this.userData=JSON.parse(JSON.stringify(t.userData)),this.needsUpdate=!0,this}setValues(t){for(let e in t){let n=t[e];if(n===void 0){Dt(`Texture.setValues(): parameter '${e}' has value of undefined.`);continue}let a=this[e];if(a===void 0){Dt(`Texture.setValues(): property '${e}' does not exist.`);continue}a&&n&&a.isVector2&&n.isVector2||a&&n&&a.isVector3&&n.isVector3||a&&n&&a.isMatrix3&&n.isMatrix3?a.copy(n):this[e]=n}}toJSON(t){let e=t===void 0||typeof t=="string";if(!e&&t.textures[this.uuid]!==void 0)return t.textures[this.uuid];let n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(t).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),e||(t.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(t){if(this.mapping!==Xh)return t;if(t.applyMatrix3(this.matrix),t.x<0||t.x>1)switch(this.wrapS){case Go:t.x=t.x-Math.floor(t.x);break;case ai:t.x=t.x<0?0:1;break;case Wo:Math.abs(Math.floor(t.x)%2)===1?t.x=Math.ceil(t.x)-t.x:t.x=t.x-Math.floor(t.x);break}if(t.y<0||t.y>1)switch(this.wrapT){case Go:t.y=t.y-Math.floor(t.y);break;case ai:t.y=t.y<0?0:1;break;case Wo:Math.abs(Math.floor(t.y)%2)===1?t.y=Math.ceil(t.y)-t.y:t.y=t.y-Math.floor(t.y);break}return this.flipY&&(t.y=1-t.y),t}set needsUpdate(t){t===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(t){t===!0&&this.pmremVersion++}};Sn.DEFAULT_IMAGE=null;Sn.DEFAULT_MAPPING=Xh;Sn.DEFAULT_ANISOTROPY=1;fd=class fd{constructor(t=0,e=0,n=0,a=1){this.x=t,this.y=e,this.z=n,this.w=a}get width(){return this.z}set width(t){this.z=t}get height(){return this.w}set height(t){this.w=t}set(t,e,n,a){return this.x=t,this.y=e,this.z=n,this.w=a,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this.w=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setW(t){return this.w=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;case 3:this.w=e;break;default:throw new Error("THREE.Vector4: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this.w=t.w!==void 0?t.w:1,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this.w+=t.w,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this.w+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this.w=t.w+e.w,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this.w+=t.w*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this.w-=t.w,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this.w-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this.w=t.w-e.w,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this.w*=t.w,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this.w*=t,this}applyMatrix4(t){let e=this.x,n=this.y,a=this.z,s=this.w,r=t.elements;return this.x=r[0]*e+r[4]*n+r[8]*a+r[12]*s,this.y=r[1]*e+r[5]*n+r[9]*a+r[13]*s,this.z=r[2]*e+r[6]*n+r[10]*a+r[14]*s,this.w=r[3]*e+r[7]*n+r[11]*a+r[15]*s,this}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this.w/=t.w,this}divideScalar(t){return this.multiplyScalar(1/t)}setAxisAngleFromQuaternion(t){this.w=2*Math.acos(t.w);let e=Math.sqrt(1-t.w*t.w);return e<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=t.x/e,this.y=t.y/e,this.z=t.z/e),this}setAxisAngleFromRotationMatrix(t){let e,n,a,s,c=t.elements,l=c[0],h=c[4],u=c[8],d=c[1],f=c[5],b=c[9],_=c[2],m=c[6],x=c[10];if(Math.abs(h-d)<.01&&Math.abs(u-_)<.01&&Math.abs(b-m)<.01){if(Math.abs(h+d)<.1&&Math.abs(u+_)<.1&&Math.abs(b+m)<.1&&Math.abs(l+f+x-3)<.1)return this.set(1,0,0,0),this;e=Math.PI;let w=(l+1)/2,p=(f+1)/2,y=(x+1)/2,S=(h+d)/4,g=(u+_)/4,M=(b+m)/4;return w>p&&w>y?w<.01?(n=0,a=.707106781,s=.707106781):(n=Math.sqrt(w),a=S/n,s=g/n):p>y?p<.01?(n=.707106781,a=0,s=.707106781):(a=Math.sqrt(p),n=S/a,s=M/a):y<.01?(n=.707106781,a=.707106781,s=0):(s=Math.sqrt(y),n=g/s,a=M/s),this.set(n,a,s,e),this}let v=Math.sqrt((m-b)*(m-b)+(u-_)*(u-_)+(d-h)*(d-h));return Math.abs(v)<.001&&(v=1),this.x=(m-b)/v,this.y=(u-_)/v,this.z=(d-h)/v,this.w=Math.acos((l+f+x-1)/2),this}setFromMatrixPosition(t){let e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this.w=e[15],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this.w=Math.min(this.w,t.w),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this.w=Math.max(this.w,t.w),this}clamp(t,e){return this.x=zt(this.x,t.x,e.x),this.y=zt(this.y,t.y,e.y),this.z=zt(this.z,t.z,e.z),this.w=zt(this.w,t.w,e.w),this}clampScalar(t,e){return this.x=zt(this.x,t,e),this.y=zt(this.y,t,e),this.z=zt(this.z,t,e),this.w=zt(this.w,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(zt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z+this.w*t.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this.w+=(t.w-this.w)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this.w=t.w+(e.w-t.w)*n,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z&&t.w===this.w}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this.w=t[e+3],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t[e+3]=this.w,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this.w=t.getW(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};fd.prototype.isVector4=!0;re=fd,qo=class extends qn{constructor(t=1,e=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:gn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=t,this.height=e,this.depth=n.depth,this.scissor=new re(0,0,t,e),this.scissorTest=!1,this.viewport=new re(0,0,t,e),this.textures=[];let a=n.count;for(let s=0;s<a;s++)this.textures[s]=new Sn({width:t,height:e,depth:n.depth}),this.textures[s].isRenderTargetTexture=!0,this.textures[s].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(t={}){let e={minFilter:gn,generateMipmaps:!1,flipY:!1,internalFormat:null};t.mapping!==void 0&&(e.mapping=t.mapping),t.wrapS!==void 0&&(e.wrapS=t.wrapS),t.wrapT!==void 0&&(e.wrapT=t.wrapT),t.wrapR!==void 0&&(e.wrapR=t.wrapR),t.magFilter!==void 0&&(e.magFilter=t.magFilter),t.minFilter!==void 0&&(e.minFilter=t.minFilter),t.format!==void 0&&(e.format=t.format),t.type!==void 0&&(e.type=t.type),t.anisotropy!==void 0&&(e.anisotropy=t.anisotropy),t.colorSpace!==void 0&&(e.colorSpace=t.colorSpace),t.flipY!==void 0&&(e.flipY=t.flipY),t.generateMipmaps!==void 0&&(e.generateMipmaps=t.generateMipmaps),t.mipmapsAutoUpdate!==void 0&&(e.mipmapsAutoUpdate=t.mipmapsAutoUpdate),t.internalFormat!==void 0&&(e.internalFormat=t.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(e)}get texture(){return this.textures[0]}set texture(t){this.textures[0]=t}set depthTexture(t){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),t!==null&&t.renderTarget===null&&(t.renderTarget=this),this._depthTexture=t}get depthTexture(){return this._depthTexture}setSize(t,e,n=1){if(this.width!==t||this.height!==e||this.depth!==n){this.width=t,this.height=e,this.depth=n;for(let a=0,s=this.textures.length;a<s;a++)this.textures[a].image.width=t,this.textures[a].image.height=e,this.textures[a].image.depth=n,this.textures[a].isData3DTexture!==!0&&(this.textures[a].isArrayTexture=this.textures[a].image.depth>1);this.dispose()}this.viewport.set(0,0,t,e),this.scissor.set(0,0,t,e)}clone(){return new this.constructor().copy(this)}copy(t){this.width=t.width,this.height=t.height,this.depth=t.depth,this.scissor.copy(t.scissor),this.scissorTest=t.scissorTest,this.viewport.copy(t.viewport),this.textures.length=0;for(let e=0,n=t.textures.length;e<n;e++){this.textures[e]=t.textures[e].clone(),this.textures[e].isRenderTargetTexture=!0,this.textures[e].renderTarget=this;let a=Object.assign({},t.textures[e].image);this.textures[e].source=new Ka(a)}if(this.depthBuffer=t.depthBuffer,this.stencilBuffer=t.stencilBuffer,this.resolveColorBuffer=t.resolveColorBuffer,this.resolveDepthBuffer=t.resolveDepthBuffer,this.resolveStencilBuffer=t.resolveStencilBuffer,this.storeMultisampledColorBuffer=t.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=t.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=t.storeMultisampledStencilBuffer,t.depthTexture!==null)if(t.depthTexture.renderTarget===t){let e=t.depthTexture.clone();e.renderTarget=null,this.depthTexture=e}else this.depthTexture=t.depthTexture;else this.depthTexture=null;return this.samples=t.samples,this.multiview=t.multiview,this.useArrayDepthTexture=t.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},Cn=class extends qo{constructor(t=1,e=1,n={}){super(t,e,n),this.isWebGLRenderTarget=!0}},Qs=class extends Sn{constructor(t=null,e=1,n=1,a=1){super(null),this.isDataArrayTexture=!0,this.image={data:t,width:e,height:n,depth:a},this.magFilter=Pe,this.minFilter=Pe,this.wrapR=ai,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}addLayerUpdate(t){this.layerUpdates.add(t)}clearLayerUpdates(){this.layerUpdates.clear()}},Yo=class extends Sn{constructor(t=null,e=1,n=1,a=1){super(null),this.isData3DTexture=!0,this.image={data:t,width:e,height:n,depth:a},this.magFilter=Pe,this.minFilter=Pe,this.wrapR=ai,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}},pc=class pc{constructor(t,e,n,a,s,r,o,c,l,h,u,d,f,b,_,m){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],t!==void 0&&this.set(t,e,n,a,s,r,o,c,l,h,u,d,f,b,_,m)}set(t,e,n,a,s,r,o,c,l,h,u,d,f,b,_,m){let x=this.elements;return x[0]=t,x[4]=e,x[8]=n,x[12]=a,x[1]=s,x[5]=r,x[9]=o,x[13]=c,x[2]=l,x[6]=h,x[10]=u,x[14]=d,x[3]=f,x[7]=b,x[11]=_,x[15]=m,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new pc().fromArray(this.elements)}copy(t){let e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],e[9]=n[9],e[10]=n[10],e[11]=n[11],e[12]=n[12],e[13]=n[13],e[14]=n[14],e[15]=n[15],this}copyPosition(t){let e=this.elements,n=t.elements;return e[12]=n[12],e[13]=n[13],e[14]=n[14],this}setFromMatrix3(t){let e=t.elements;return this.set(e[0],e[3],e[6],0,e[1],e[4],e[7],0,e[2],e[5],e[8],0,0,0,0,1),this}extractBasis(t,e,n){return this.determinantAffine()===0?(t.set(1,0,0),e.set(0,1,0),n.set(0,0,1),this):(t.setFromMatrixColumn(this,0),e.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(t,e,n){return this.set(t.x,e.x,n.x,0,t.y,e.y,n.y,0,t.z,e.z,n.z,0,0,0,0,1),this}extractRotation(t){if(t.determinantAffine()===0)return this.identity();let e=this.elements,n=t.elements,a=1/Na.setFromMatrixColumn(t,0).length(),s=1/Na.setFromMatrixColumn(t,1).length(),r=1/Na.setFromMatrixColumn(t,2).length();return e[0]=n[0]*a,e[1]=n[1]*a,e[2]=n[2]*a,e[3]=0,e[4]=n[4]*s,e[5]=n[5]*s,e[6]=n[6]*s,e[7]=0,e[8]=n[8]*r,e[9]=n[9]*r,e[10]=n[10]*r,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromEuler(t){let e=this.elements,n=t.x,a=t.y,s=t.z,r=Math.cos(n),o=Math.sin(n),c=Math.cos(a),l=Math.sin(a),h=Math.cos(s),u=Math.sin(s);if(t.order==="XYZ"){let d=r*h,f=r*u,b=o*h,_=o*u;e[0]=c*h,e[4]=-c*u,e[8]=l,e[1]=f+b*l,e[5]=d-_*l,e[9]=-o*c,e[2]=_-d*l,e[6]=b+f*l,e[10]=r*c}else if(t.order==="YXZ"){let d=c*h,f=c*u,b=l*h,_=l*u;e[0]=d+_*o,e[4]=b*o-f,e[8]=r*l,e[1]=r*u,e[5]=r*h,e[9]=-o,e[2]=f*o-b,e[6]=_+d*o,e[10]=r*c}else if(t.order==="ZXY"){let d=c*h,f=c*u,b=l*h,_=l*u;e[0]=d-_*o,e[4]=-r*u,e[8]=b+f*o,e[1]=f+b*o,e[5]=r*h,e[9]=_-d*o,e[2]=-r*l,e[6]=o,e[10]=r*c}else if(t.order==="ZYX"){let d=r*h,f=r*u,b=o*h,_=o*u;e[0]=c*h,e[4]=b*l-f,e[8]=d*l+_,e[1]=c*u,e[5]=_*l+d,e[9]=f*l-b,e[2]=-l,e[6]=o*c,e[10]=r*c}else if(t.order==="YZX"){let d=r*c,f=r*l,b=o*c,_=o*l;e[0]=c*h,e[4]=_-d*u,e[8]=b*u+f,e[1]=u,e[5]=r*h,e[9]=-o*h,e[2]=-l*h,e[6]=f*u+b,e[10]=d-_*u}else if(t.order==="XZY"){let d=r*c,f=r*l,b=o*c,_=o*l;e[0]=c*h,e[4]=-u,e[8]=l*h,e[1]=d*u+_,e[5]=r*h,e[9]=f*u-b,e[2]=b*u-f,e[6]=o*h,e[10]=_*u+d}return e[3]=0,e[7]=0,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromQuaternion(t){return this.compose(ub,t,fb)}lookAt(t,e,n){let a=this.elements;return En.subVectors(t,e),En.lengthSq()===0&&(En.z=1),En.normalize(),Bi.crossVectors(n,En),Bi.lengthSq()===0&&(Math.abs(n.z)===1?En.x+=1e-4:En.z+=1e-4,En.normalize(),Bi.crossVectors(n,En)),Bi.normalize(),ro.crossVectors(En,Bi),a[0]=Bi.x,a[4]=ro.x,a[8]=En.x,a[1]=Bi.y,a[5]=ro.y,a[9]=En.y,a[2]=Bi.z,a[6]=ro.z,a[10]=En.z,this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){let n=t.elements,a=e.elements,s=this.elements,r=n[0],o=n[4],c=n[8],l=n[12],h=n[1],u=n[5],d=n[9],f=n[13],b=n[2],_=n[6],m=n[10],x=n[14],v=n[3],w=n[7],p=n[11],y=n[15],S=a[0],g=a[4],M=a[8],E=a[12],A=a[1],I=a[5],C=a[9],P=a[13],N=a[2],U=a[6],z=a[10],F=a[14],K=a[3],H=a[7],J=a[11],tt=a[15];return s[0]=r*S+o*A+c*N+l*K,s[4]=r*g+o*I+c*U+l*H,s[8]=r*M+o*C+c*z+l*J,s[12]=r*E+o*P+c*F+l*tt,s[1]=h*S+u*A+d*N+f*K,s[5]=h*g+u*I+d*U+f*H,s[9]=h*M+u*C+d*z+f*J,s[13]=h*E+u*P+d*F+f*tt,s[2]=b*S+_*A+m*N+x*K,s[6]=b*g+_*I+m*U+x*H,s[10]=b*M+_*C+m*z+x*J,s[14]=b*E+_*P+m*F+x*tt,s[3]=v*S+w*A+p*N+y*K,s[7]=v*g+w*I+p*U+y*H,s[11]=v*M+w*C+p*z+y*J,s[15]=v*E+w*P+p*F+y*tt,this}multiplyScalar(t){let e=this.elements;return e[0]*=t,e[4]*=t,e[8]*=t,e[12]*=t,e[1]*=t,e[5]*=t,e[9]*=t,e[13]*=t,e[2]*=t,e[6]*=t,e[10]*=t,e[14]*=t,e[3]*=t,e[7]*=t,e[11]*=t,e[15]*=t,this}determinant(){let t=this.elements,e=t[0],n=t[4],a=t[8],s=t[12],r=t[1],o=t[5],c=t[9],l=t[13],h=t[2],u=t[6],d=t[10],f=t[14],b=t[3],_=t[7],m=t[11],x=t[15],v=c*f-l*d,w=o*f-l*u,p=o*d-c*u,y=r*f-l*h,S=r*d-c*h,g=r*u-o*h;return e*(_*v-m*w+x*p)-n*(b*v-m*y+x*S)+a*(b*w-_*y+x*g)-s*(b*p-_*S+m*g)}determinantAffine(){let t=this.elements,e=t[0],n=t[4],a=t[8],s=t[1],r=t[5],o=t[9],c=t[2],l=t[6],h=t[10];return e*(r*h-o*l)-n*(s*h-o*c)+a*(s*l-r*c)}transpose(){let t=this.elements,e;return e=t[1],t[1]=t[4],t[4]=e,e=t[2],t[2]=t[8],t[8]=e,e=t[6],t[6]=t[9],t[9]=e,e=t[3],t[3]=t[12],t[12]=e,e=t[7],t[7]=t[13],t[13]=e,e=t[11],t[11]=t[14],t[14]=e,this}setPosition(t,e,n){let a=this.elements;return t.isVector3?(a[12]=t.x,a[13]=t.y,a[14]=t.z):(a[12]=t,a[13]=e,a[14]=n),this}invert(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8],u=t[9],d=t[10],f=t[11],b=t[12],_=t[13],m=t[14],x=t[15],v=e*o-n*r,w=e*c-a*r,p=e*l-s*r,y=n*c-a*o,S=n*l-s*o,g=a*l-s*c,M=h*_-u*b,E=h*m-d*b,A=h*x-f*b,I=u*m-d*_,C=u*x-f*_,P=d*x-f*m,N=v*P-w*C+p*I+y*A-S*E+g*M;if(N===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let U=1/N;return t[0]=(o*P-c*C+l*I)*U,t[1]=(a*C-n*P-s*I)*U,t[2]=(_*g-m*S+x*y)*U,t[3]=(d*S-u*g-f*y)*U,t[4]=(c*A-r*P-l*E)*U,t[5]=(e*P-a*A+s*E)*U,t[6]=(m*p-b*g-x*w)*U,t[7]=(h*g-d*p+f*w)*U,t[8]=(r*C-o*A+l*M)*U,t[9]=(n*A-e*C-s*M)*U,t[10]=(b*S-_*p+x*v)*U,t[11]=(u*p-h*S-f*v)*U,t[12]=(o*E-r*I-c*M)*U,t[13]=(e*I-n*E+a*M)*U,t[14]=(_*w-b*y-m*v)*U,t[15]=(h*y-u*w+d*v)*U,this}scale(t){let e=this.elements,n=t.x,a=t.y,s=t.z;return e[0]*=n,e[4]*=a,e[8]*=s,e[1]*=n,e[5]*=a,e[9]*=s,e[2]*=n,e[6]*=a,e[10]*=s,e[3]*=n,e[7]*=a,e[11]*=s,this}getMaxScaleOnAxis(){let t=this.elements,e=t[0]*t[0]+t[1]*t[1]+t[2]*t[2],n=t[4]*t[4]+t[5]*t[5]+t[6]*t[6],a=t[8]*t[8]+t[9]*t[9]+t[10]*t[10];return Math.sqrt(Math.max(e,n,a))}makeTranslation(t,e,n){return t.isVector3?this.set(1,0,0,t.x,0,1,0,t.y,0,0,1,t.z,0,0,0,1):this.set(1,0,0,t,0,1,0,e,0,0,1,n,0,0,0,1),this}makeRotationX(t){let e=Math.cos(t),n=Math.sin(t);return this.set(1,0,0,0,0,e,-n,0,0,n,e,0,0,0,0,1),this}makeRotationY(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,0,n,0,0,1,0,0,-n,0,e,0,0,0,0,1),this}makeRotationZ(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,0,n,e,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(t,e){let n=Math.cos(e),a=Math.sin(e),s=1-n,r=t.x,o=t.y,c=t.z,l=s*r,h=s*o;return this.set(l*r+n,l*o-a*c,l*c+a*o,0,l*o+a*c,h*o+n,h*c-a*r,0,l*c-a*o,h*c+a*r,s*c*c+n,0,0,0,0,1),this}makeScale(t,e,n){return this.set(t,0,0,0,0,e,0,0,0,0,n,0,0,0,0,1),this}makeShear(t,e,n,a,s,r){return this.set(1,n,s,0,t,1,r,0,e,a,1,0,0,0,0,1),this}compose(t,e,n){let a=this.elements,s=e._x,r=e._y,o=e._z,c=e._w,l=s+s,h=r+r,u=o+o,d=s*l,f=s*h,b=s*u,_=r*h,m=r*u,x=o*u,v=c*l,w=c*h,p=c*u,y=n.x,S=n.y,g=n.z;return a[0]=(1-(_+x))*y,a[1]=(f+p)*y,a[2]=(b-w)*y,a[3]=0,a[4]=(f-p)*S,a[5]=(1-(d+x))*S,a[6]=(m+v)*S,a[7]=0,a[8]=(b+w)*g,a[9]=(m-v)*g,a[10]=(1-(d+_))*g,a[11]=0,a[12]=t.x,a[13]=t.y,a[14]=t.z,a[15]=1,this}decompose(t,e,n){let a=this.elements;t.x=a[12],t.y=a[13],t.z=a[14];let s=this.determinantAffine();if(s===0)return n.set(1,1,1),e.identity(),this;let r=Na.set(a[0],a[1],a[2]).length(),o=Na.set(a[4],a[5],a[6]).length(),c=Na.set(a[8],a[9],a[10]).length();s<0&&(r=-r),Wn.copy(this);let l=1/r,h=1/o,u=1/c;return Wn.elements[0]*=l,Wn.elements[1]*=l,Wn.elements[2]*=l,Wn.elements[4]*=h,Wn.elements[5]*=h,Wn.elements[6]*=h,Wn.elements[8]*=u,Wn.elements[9]*=u,Wn.elements[10]*=u,e.setFromRotationMatrix(Wn),n.x=r,n.y=o,n.z=c,this}makePerspective(t,e,n,a,s,r,o=On,c=!1){let l=this.elements,h=2*s/(e-t),u=2*s/(n-a),d=(e+t)/(e-t),f=(n+a)/(n-a),b,_;if(c)b=s/(r-s),_=r*s/(r-s);else if(o===On)b=-(r+s)/(r-s),_=-2*r*s/(r-s);else if(o===qa)b=-r/(r-s),_=-r*s/(r-s);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=d,l[12]=0,l[1]=0,l[5]=u,l[9]=f,l[13]=0,l[2]=0,l[6]=0,l[10]=b,l[14]=_,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(t,e,n,a,s,r,o=On,c=!1){let l=this.elements,h=2/(e-t),u=2/(n-a),d=-(e+t)/(e-t),f=-(n+a)/(n-a),b,_;if(c)b=1/(r-s),_=r/(r-s);else if(o===On)b=-2/(r-s),_=-(r+s)/(r-s);else if(o===qa)b=-1/(r-s),_=-s/(r-s);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=0,l[12]=d,l[1]=0,l[5]=u,l[9]=0,l[13]=f,l[2]=0,l[6]=0,l[10]=b,l[14]=_,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(t){let e=this.elements,n=t.elements;for(let a=0;a<16;a++)if(e[a]!==n[a])return!1;return!0}fromArray(t,e=0){for(let n=0;n<16;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){let n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t[e+9]=n[9],t[e+10]=n[10],t[e+11]=n[11],t[e+12]=n[12],t[e+13]=n[13],t[e+14]=n[14],t[e+15]=n[15],t}};pc.prototype.isMatrix4=!0;se=pc,Na=new k,Wn=new se,ub=new k(0,0,0),fb=new k(1,1,1),Bi=new k,ro=new k,En=new k,Pu=new se,Lu=new Rn,Ti=class i{constructor(t=0,e=0,n=0,a=i.DEFAULT_ORDER){this.isEuler=!0,this._x=t,this._y=e,this._z=n,this._order=a}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get order(){return this._order}set order(t){this._order=t,this._onChangeCallback()}set(t,e,n,a=this._order){return this._x=t,this._y=e,this._z=n,this._order=a,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(t){return this._x=t._x,this._y=t._y,this._z=t._z,this._order=t._order,this._onChangeCallback(),this}setFromRotationMatrix(t,e=this._order,n=!0){let a=t.elements,s=a[0],r=a[4],o=a[8],c=a[1],l=a[5],h=a[9],u=a[2],d=a[6],f=a[10];switch(e){case"XYZ":this._y=Math.asin(zt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,f),this._z=Math.atan2(-r,s)):(this._x=Math.atan2(d,l),this._z=0);break;case"YXZ":this._x=Math.asin(-zt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,f),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-u,s),this._z=0);break;case"ZXY":this._x=Math.asin(zt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(-u,f),this._z=Math.atan2(-r,l)):(this._y=0,this._z=Math.atan2(c,s));break;case"ZYX":this._y=Math.asin(-zt(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(d,f),this._z=Math.atan2(c,s)):(this._x=0,this._z=Math.atan2(-r,l));break;case"YZX":this._z=Math.asin(zt(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-h,l),this._y=Math.atan2(-u,s)):(this._x=0,this._y=Math.atan2(o,f));break;case"XZY":this._z=Math.asin(-zt(r,-1,1)),Math.abs(r)<.9999999?(this._x=Math.atan2(d,l),this._y=Math.atan2(o,s)):(this._x=Math.atan2(-h,f),this._y=0);break;default:Dt("Euler: .setFromRotationMatrix() encountered an unknown order: "+e)}return this._order=e,n===!0&&this._onChangeCallback(),this}setFromQuaternion(t,e,n){return Pu.makeRotationFromQuaternion(t),this.setFromRotationMatrix(Pu,e,n)}setFromVector3(t,e=this._order){return this.set(t.x,t.y,t.z,e)}reorder(t){return Lu.setFromEuler(this),this.setFromQuaternion(Lu,t)}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._order===this._order}fromArray(t){return this._x=t[0],this._y=t[1],this._z=t[2],t[3]!==void 0&&(this._order=t[3]),this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._order,t}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};Ti.DEFAULT_ORDER="XYZ";Za=class{constructor(){this.mask=1}set(t){this.mask=(1<<t|0)>>>0}enable(t){this.mask|=1<<t|0}enableAll(){this.mask=-1}toggle(t){this.mask^=1<<t|0}disable(t){this.mask&=~(1<<t|0)}disableAll(){this.mask=0}test(t){return(this.mask&t.mask)!==0}isEnabled(t){return(this.mask&(1<<t|0))!==0}},pb=0,Du=new k,Pa=new Rn,xi=new se,oo=new k,ks=new k,mb=new k,gb=new Rn,Uu=new k(1,0,0),Ou=new k(0,1,0),Fu=new k(0,0,1),Bu={type:"added"},bb={type:"removed"},La={type:"childadded",child:null},nh={type:"childremoved",child:null},Oe=class i extends qn{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:pb++}),this.uuid=Ji(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=i.DEFAULT_UP.clone();let t=new k,e=new Ti,n=new Rn,a=new k(1,1,1);function s(){n.setFromEuler(e,!1)}function r(){e.setFromQuaternion(n,void 0,!1)}e._onChange(s),n._onChange(r),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:t},rotation:{configurable:!0,enumerable:!0,value:e},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:a},modelViewMatrix:{value:new se},normalMatrix:{value:new Bt}}),this.matrix=new se,this.matrixWorld=new se,this.matrixAutoUpdate=i.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=i.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Za,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(t){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(t),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(t){return this.quaternion.premultiply(t),this}setRotationFromAxisAngle(t,e){this.quaternion.setFromAxisAngle(t,e)}setRotationFromEuler(t){this.quaternion.setFromEuler(t,!0)}setRotationFromMatrix(t){this.quaternion.setFromRotationMatrix(t)}setRotationFromQuaternion(t){this.quaternion.copy(t)}rotateOnAxis(t,e){return Pa.setFromAxisAngle(t,e),this.quaternion.multiply(Pa),this}rotateOnWorldAxis(t,e){return Pa.setFromAxisAngle(t,e),this.quaternion.premultiply(Pa),this}rotateX(t){return this.rotateOnAxis(Uu,t)}rotateY(t){return this.rotateOnAxis(Ou,t)}rotateZ(t){return this.rotateOnAxis(Fu,t)}translateOnAxis(t,e){return Du.copy(t).applyQuaternion(this.quaternion),this.position.add(Du.multiplyScalar(e)),this}translateX(t){return this.translateOnAxis(Uu,t)}translateY(t){return this.translateOnAxis(Ou,t)}translateZ(t){return this.translateOnAxis(Fu,t)}localToWorld(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(this.matrixWorld)}worldToLocal(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(xi.copy(this.matrixWorld).invert())}lookAt(t,e,n){t.isVector3?oo.copy(t):oo.set(t,e,n);let a=this.parent;this.updateWorldMatrix(!0,!1),ks.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?xi.lookAt(ks,oo,this.up):xi.lookAt(oo,ks,this.up),this.quaternion.setFromRotationMatrix(xi),a&&(xi.extractRotation(a.matrixWorld),Pa.setFromRotationMatrix(xi),this.quaternion.premultiply(Pa.invert()))}add(t){if(arguments.length>1){for(let e=0;e<arguments.length;e++)this.add(arguments[e]);return this}return t===this?(Ft("Object3D.add: object can't be added as a child of itself.",t),this):(t&&t.isObject3D?(t.removeFromParent(),t.parent=this,this.children.push(t),t.dispatchEvent(Bu),La.child=t,this.dispatchEvent(La),La.child=null):Ft("Object3D.add: object not an instance of THREE.Object3D.",t),this)}remove(t){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}let e=this.children.indexOf(t);return e!==-1&&(t.parent=null,this.children.splice(e,1),t.dispatchEvent(bb),nh.child=t,this.dispatchEvent(nh),nh.child=null),this}removeFromParent(){let t=this.parent;return t!==null&&t.remove(this),this}clear(){return this.remove(...this.children)}attach(t){return this.updateWorldMatrix(!0,!1),xi.copy(this.matrixWorld).invert(),t.parent!==null&&(t.parent.updateWorldMatrix(!0,!1),xi.multiply(t.parent.matrixWorld)),t.applyMatrix4(xi),t.removeFromParent(),t.parent=this,this.children.push(t),t.updateWorldMatrix(!1,!0),t.dispatchEvent(Bu),La.child=t,this.dispatchEvent(La),La.child=null,this}getObjectById(t){return this.getObjectByProperty("id",t)}getObjectByName(t){return this.getObjectByProperty("name",t)}getObjectByProperty(t,e){if(this[t]===e)return this;for(let n=0,a=this.children.length;n<a;n++){let r=this.children[n].getObjectByProperty(t,e);if(r!==void 0)return r}}getObjectsByProperty(t,e,n=[]){this[t]===e&&n.push(this);let a=this.children;for(let s=0,r=a.length;s<r;s++)a[s].getObjectsByProperty(t,e,n);return n}getWorldPosition(t){return this.updateWorldMatrix(!0,!1),t.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ks,t,mb),t}getWorldScale(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ks,gb,t),t}getWorldDirection(t){this.updateWorldMatrix(!0,!1);let e=this.matrixWorld.elements;return t.set(e[8],e[9],e[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(t){t(this);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].traverse(t)}traverseVisible(t){if(this.visible===!1)return;t(this);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].traverseVisible(t)}traverseAncestors(t){let e=this.parent;e!==null&&(t(e),e.traverseAncestors(t))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let t=this.pivot;if(t!==null){let e=t.x,n=t.y,a=t.z,s=this.matrix.elements;s[12]+=e-s[0]*e-s[4]*n-s[8]*a,s[13]+=n-s[1]*e-s[5]*n-s[9]*a,s[14]+=a-s[2]*e-s[6]*n-s[10]*a}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(t){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||t)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,t=!0);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].updateMatrixWorld(t)}updateWorldMatrix(t,e,n=!1){let a=this.parent;if(t===!0&&a!==null&&a.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),e===!0){let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].updateWorldMatrix(!1,!0,n)}}toJSON(t){let e=t===void 0||typeof t=="string",n={};e&&(t={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let a={};a.uuid=this.uuid,a.type=this.type,a.name=this.name,a.castShadow=this.castShadow,a.receiveShadow=this.receiveShadow,a.visible=this.visible,a.frustumCulled=this.frustumCulled,a.renderOrder=this.renderOrder,a.static=this.static,a.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(a.userData=this.userData),a.layers=this.layers.mask,a.matrix=this.matrix.toArray(),a.up=this.up.toArray(),this.pivot!==null&&(a.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(a.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(a.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(a.type="InstancedMesh",a.count=this.count,a.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(a.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(a.type="BatchedMesh",a.perObjectFrustumCulled=this.perObjectFrustumCulled,a.sortObjects=this.sortObjects,a.drawRanges=this._drawRanges,a.reservedRanges=this._reservedRanges,a.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),a.instanceInfo=this._instanceInfo.map(o=>({...o})),a.availableInstanceIds=this._availableInstanceIds.slice(),a.availableGeometryIds=this._availableGeometryIds.slice(),a.nextIndexStart=this._nextIndexStart,a.nextVertexStart=this._nextVertexStart,a.geometryCount=this._geometryCount,a.maxInstanceCount=this._maxInstanceCount,a.maxVertexCount=this._maxVertexCount,a.maxIndexCount=this._maxIndexCount,a.geometryInitialized=this._geometryInitialized,a.matricesTexture=this._matricesTexture.toJSON(t),a.indirectTexture=this._indirectTexture.toJSON(t),this._colorsTexture!==null&&(a.colorsTexture=this._colorsTexture.toJSON(t)),this.boundingSphere!==null&&(a.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(a.boundingBox=this.boundingBox.toJSON()));function s(o,c){return o[c.uuid]===void 0&&(o[c.uuid]=c.toJSON(t)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?a.background=this.background.toJSON():this.background.isTexture&&(a.background=this.background.toJSON(t).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(a.environment=this.environment.toJSON(t).uuid);else if(this.isMesh||this.isLine||this.isPoints){a.geometry=s(t.geometries,this.geometry);let o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){let c=o.shapes;if(Array.isArray(c))for(let l=0,h=c.length;l<h;l++){let u=c[l];s(t.shapes,u)}else s(t.shapes,c)}}if(this.isSkinnedMesh&&(a.bindMode=this.bindMode,a.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(s(t.skeletons,this.skeleton),a.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let o=[];for(let c=0,l=this.material.length;c<l;c++)o.push(s(t.materials,this.material[c]));a.material=o}else a.material=s(t.materials,this.material);if(this.children.length>0){a.children=[];for(let o=0;o<this.children.length;o++)a.children.push(this.children[o].toJSON(t).object)}if(this.animations.length>0){a.animations=[];for(let o=0;o<this.animations.length;o++){let c=this.animations[o];a.animations.push(s(t.animations,c))}}if(e){let o=r(t.geometries),c=r(t.materials),l=r(t.textures),h=r(t.images),u=r(t.shapes),d=r(t.skeletons),f=r(t.animations),b=r(t.nodes);o.length>0&&(n.geometries=o),c.length>0&&(n.materials=c),l.length>0&&(n.textures=l),h.length>0&&(n.images=h),u.length>0&&(n.shapes=u),d.length>0&&(n.skeletons=d),f.length>0&&(n.animations=f),b.length>0&&(n.nodes=b)}return n.object=a,n;function r(o){let c=[];for(let l in o){let h=o[l];delete h.metadata,c.push(h)}return c}}clone(t){return new this.constructor().copy(this,t)}copy(t,e=!0){if(this.name=t.name,this.up.copy(t.up),this.position.copy(t.position),this.rotation.order=t.rotation.order,this.quaternion.copy(t.quaternion),this.scale.copy(t.scale),this.pivot=t.pivot!==null?t.pivot.clone():null,this.matrix.copy(t.matrix),this.matrixWorld.copy(t.matrixWorld),this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrixWorldAutoUpdate=t.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=t.matrixWorldNeedsUpdate,this.layers.mask=t.layers.mask,this.visible=t.visible,this.castShadow=t.castShadow,this.receiveShadow=t.receiveShadow,this.frustumCulled=t.frustumCulled,this.renderOrder=t.renderOrder,this.static=t.static,this.animations=t.animations.slice(),this.userData=JSON.parse(JSON.stringify(t.userData)),e===!0)for(let n=0;n<t.children.length;n++){let a=t.children[n];this.add(a.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};Oe.DEFAULT_UP=new k(0,1,0);Oe.DEFAULT_MATRIX_AUTO_UPDATE=!0;Oe.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;Si=class extends Oe{constructor(){super(),this.isGroup=!0,this.type="Group"}},xb={type:"move"},Qa=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Si,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Si,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new k,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new k),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Si,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new k,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new k,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(t){return this._targetRay!==null&&this._targetRay.dispatchEvent(t),this._grip!==null&&this._grip.dispatchEvent(t),this._hand!==null&&this._hand.dispatchEvent(t),this}connect(t){if(t&&t.hand){let e=this._hand;if(e)for(let n of t.hand.values())this._getHandJoint(e,n)}return this.dispatchEvent({type:"connected",data:t}),this}disconnect(t){return this.dispatchEvent({type:"disconnected",data:t}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(t,e,n){let a=null,s=null,r=null,o=this._targetRay,c=this._grip,l=this._hand;if(t&&e.session.visibilityState!=="visible-blurred"){if(l&&t.hand){r=!0;for(let _ of t.hand.values()){let m=e.getJointPose(_,n),x=this._getHandJoint(l,_);m!==null&&(x.matrix.fromArray(m.transform.matrix),x.matrix.decompose(x.position,x.quaternion,x.scale),x.matrixWorldNeedsUpdate=!0,x.jointRadius=m.radius),x.visible=m!==null}let h=l.joints["index-finger-tip"],u=l.joints["thumb-tip"],d=h.position.distanceTo(u.position),f=.02,b=.005;l.inputState.pinching&&d>f+b?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:t.handedness,target:this})):!l.inputState.pinching&&d<=f-b&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:t.handedness,target:this}))}else c!==null&&t.gripSpace&&(s=e.getPose(t.gripSpace,n),s!==null&&(c.matrix.fromArray(s.transform.matrix),c.matrix.decompose(c.position,c.quaternion,c.scale),c.matrixWorldNeedsUpdate=!0,s.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(s.linearVelocity)):c.hasLinearVelocity=!1,s.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(s.angularVelocity)):c.hasAngularVelocity=!1,c.eventsEnabled&&c.dispatchEvent({type:"gripUpdated",data:t,target:this})));o!==null&&(a=e.getPose(t.targetRaySpace,n),a===null&&s!==null&&(a=s),a!==null&&(o.matrix.fromArray(a.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,a.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(a.linearVelocity)):o.hasLinearVelocity=!1,a.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(a.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(xb)))}return o!==null&&(o.visible=a!==null),c!==null&&(c.visible=s!==null),l!==null&&(l.visible=r!==null),this}_getHandJoint(t,e){if(t.joints[e.jointName]===void 0){let n=new Si;n.matrixAutoUpdate=!1,n.visible=!1,t.joints[e.jointName]=n,t.add(n)}return t.joints[e.jointName]}},qf={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},ki={h:0,s:0,l:0},co={h:0,s:0,l:0};Ht=class{constructor(t,e,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(t,e,n)}set(t,e,n){if(e===void 0&&n===void 0){let a=t;a&&a.isColor?this.copy(a):typeof a=="number"?this.setHex(a):typeof a=="string"&&this.setStyle(a)}else this.setRGB(t,e,n);return this}setScalar(t){return this.r=t,this.g=t,this.b=t,this}setHex(t,e=In){return t=Math.floor(t),this.r=(t>>16&255)/255,this.g=(t>>8&255)/255,this.b=(t&255)/255,Jt.colorSpaceToWorking(this,e),this}setRGB(t,e,n,a=Jt.workingColorSpace){return this.r=t,this.g=e,this.b=n,Jt.colorSpaceToWorking(this,a),this}setHSL(t,e,n,a=Jt.workingColorSpace){if(t=nd(t,1),e=zt(e,0,1),n=zt(n,0,1),e===0)this.r=this.g=this.b=n;else{let s=n<=.5?n*(1+e):n+e-n*e,r=2*n-s;this.r=ih(r,s,t+1/3),this.g=ih(r,s,t),this.b=ih(r,s,t-1/3)}return Jt.colorSpaceToWorking(this,a),this}setStyle(t,e=In){function n(s){s!==void 0&&parseFloat(s)<1&&Dt("Color: Alpha component of "+t+" will be ignored.")}let a;if(a=/^(\w+)\(([^\)]*)\)/.exec(t)){let s,r=a[1],o=a[2];switch(r){case"rgb":case"rgba":if(s=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(255,parseInt(s[1],10))/255,Math.min(255,parseInt(s[2],10))/255,Math.min(255,parseInt(s[3],10))/255,e);if(s=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(100,parseFloat(s[1]))/100,Math.min(100,parseFloat(s[2]))/100,Math.min(100,parseFloat(s[3]))/100,e);break;case"hsl":case"hsla":if(s=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setHSL(parseFloat(s[1])/360,parseFloat(s[2])/100,parseFloat(s[3])/100,e);break;default:Dt("Color: Unknown color model "+t)}}else if(a=/^\#([A-Fa-f\d]+)$/.exec(t)){let s=a[1],r=s.length;if(r===3)return this.setRGB(parseInt(s.charAt(0),16)/15,parseInt(s.charAt(1),16)/15,parseInt(s.charAt(2),16)/15,e);if(r===6)return this.setHex(parseInt(s,16),e);Dt("Color: Invalid hex color "+t)}else if(t&&t.length>0)return this.setColorName(t,e);return this}setColorName(t,e=In){let n=qf[t.toLowerCase()];return n!==void 0?this.setHex(n,e):Dt("Color: Unknown color "+t),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(t){return this.r=t.r,this.g=t.g,this.b=t.b,this}copySRGBToLinear(t){return this.r=wi(t.r),this.g=wi(t.g),this.b=wi(t.b),this}copyLinearToSRGB(t){return this.r=ja(t.r),this.g=ja(t.g),this.b=ja(t.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(t=In){return Jt.workingToColorSpace(en.copy(this),t),Math.round(zt(en.r*255,0,255))*65536+Math.round(zt(en.g*255,0,255))*256+Math.round(zt(en.b*255,0,255))}getHexString(t=In){return("000000"+this.getHex(t).toString(16)).slice(-6)}getHSL(t,e=Jt.workingColorSpace){Jt.workingToColorSpace(en.copy(this),e);let n=en.r,a=en.g,s=en.b,r=Math.max(n,a,s),o=Math.min(n,a,s),c,l,h=(o+r)/2;if(o===r)c=0,l=0;else{let u=r-o;switch(l=h<=.5?u/(r+o):u/(2-r-o),r){case n:c=(a-s)/u+(a<s?6:0);break;case a:c=(s-n)/u+2;break;case s:c=(n-a)/u+4;break}c/=6}return t.h=c,t.s=l,t.l=h,t}getRGB(t,e=Jt.workingColorSpace){return Jt.workingToColorSpace(en.copy(this),e),t.r=en.r,t.g=en.g,t.b=en.b,t}getStyle(t=In){Jt.workingToColorSpace(en.copy(this),t);let e=en.r,n=en.g,a=en.b;return t!==In?`color(${t} ${e.toFixed(3)} ${n.toFixed(3)} ${a.toFixed(3)})`:`rgb(${Math.round(e*255)},${Math.round(n*255)},${Math.round(a*255)})`}offsetHSL(t,e,n){return this.getHSL(ki),this.setHSL(ki.h+t,ki.s+e,ki.l+n)}add(t){return this.r+=t.r,this.g+=t.g,this.b+=t.b,this}addColors(t,e){return this.r=t.r+e.r,this.g=t.g+e.g,this.b=t.b+e.b,this}addScalar(t){return this.r+=t,this.g+=t,this.b+=t,this}sub(t){return this.r=Math.max(0,this.r-t.r),this.g=Math.max(0,this.g-t.g),this.b=Math.max(0,this.b-t.b),this}multiply(t){return this.r*=t.r,this.g*=t.g,this.b*=t.b,this}multiplyScalar(t){return this.r*=t,this.g*=t,this.b*=t,this}lerp(t,e){return this.r+=(t.r-this.r)*e,this.g+=(t.g-this.g)*e,this.b+=(t.b-this.b)*e,this}lerpColors(t,e,n){return this.r=t.r+(e.r-t.r)*n,this.g=t.g+(e.g-t.g)*n,this.b=t.b+(e.b-t.b)*n,this}lerpHSL(t,e){this.getHSL(ki),t.getHSL(co);let n=Xs(ki.h,co.h,e),a=Xs(ki.s,co.s,e),s=Xs(ki.l,co.l,e);return this.setHSL(n,a,s),this}setFromVector3(t){return this.r=t.x,this.g=t.y,this.b=t.z,this}applyMatrix3(t){let e=this.r,n=this.g,a=this.b,s=t.elements;return this.r=s[0]*e+s[3]*n+s[6]*a,this.g=s[1]*e+s[4]*n+s[7]*a,this.b=s[2]*e+s[5]*n+s[8]*a,this}equals(t){return t.r===this.r&&t.g===this.g&&t.b===this.b}fromArray(t,e=0){return this.r=t[e],this.g=t[e+1],this.b=t[e+2],this}toArray(t=[],e=0){return t[e]=this.r,t[e+1]=this.g,t[e+2]=this.b,t}fromBufferAttribute(t,e){return this.r=t.getX(e),this.g=t.getY(e),this.b=t.getZ(e),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},en=new Ht;Ht.NAMES=qf;$s=class extends Oe{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ti,this.environmentIntensity=1,this.environmentRotation=new Ti,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(t,e){return super.copy(t,e),this.background=t.background!==null?t.background.clone():null,this.environment=t.environment!==null?t.environment.clone():null,this.fog=t.fog!==null?t.fog.clone():null,this.backgroundBlurriness=t.backgroundBlurriness,this.backgroundIntensity=t.backgroundIntensity,this.backgroundRotation.copy(t.backgroundRotation),this.environmentIntensity=t.environmentIntensity,this.environmentRotation.copy(t.environmentRotation),this.overrideMaterial=t.overrideMaterial!==null?t.overrideMaterial.clone():null,this.matrixAutoUpdate=t.matrixAutoUpdate,this}toJSON(t){let e=super.toJSON(t);return this.fog!==null&&(e.object.fog=this.fog.toJSON()),e.object.backgroundBlurriness=this.backgroundBlurriness,e.object.backgroundIntensity=this.backgroundIntensity,e.object.backgroundRotation=this.backgroundRotation.toArray(),e.object.environmentIntensity=this.environmentIntensity,e.object.environmentRotation=this.environmentRotation.toArray(),e}},jn=new k,yi=new k,ah=new k,_i=new k,Da=new k,Ua=new k,ku=new k,sh=new k,rh=new k,oh=new k,ch=new re,lh=new re,hh=new re,ii=class i{constructor(t=new k,e=new k,n=new k){this.a=t,this.b=e,this.c=n}static getNormal(t,e,n,a){a.subVectors(n,e),jn.subVectors(t,e),a.cross(jn);let s=a.lengthSq();return s>0?a.multiplyScalar(1/Math.sqrt(s)):a.set(0,0,0)}static getBarycoord(t,e,n,a,s){jn.subVectors(a,e),yi.subVectors(n,e),ah.subVectors(t,e);let r=jn.dot(jn),o=jn.dot(yi),c=jn.dot(ah),l=yi.dot(yi),h=yi.dot(ah),u=r*l-o*o;if(u===0)return s.set(0,0,0),null;let d=1/u,f=(l*c-o*h)*d,b=(r*h-o*c)*d;return s.set(1-f-b,b,f)}static containsPoint(t,e,n,a){return this.getBarycoord(t,e,n,a,_i)===null?!1:_i.x>=0&&_i.y>=0&&_i.x+_i.y<=1}static getInterpolation(t,e,n,a,s,r,o,c){return this.getBarycoord(t,e,n,a,_i)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(s,_i.x),c.addScaledVector(r,_i.y),c.addScaledVector(o,_i.z),c)}static getInterpolatedAttribute(t,e,n,a,s,r){return ch.setScalar(0),lh.setScalar(0),hh.setScalar(0),ch.fromBufferAttribute(t,e),lh.fromBufferAttribute(t,n),hh.fromBufferAttribute(t,a),r.setScalar(0),r.addScaledVector(ch,s.x),r.addScaledVector(lh,s.y),r.addScaledVector(hh,s.z),r}static isFrontFacing(t,e,n,a){return jn.subVectors(n,e),yi.subVectors(t,e),jn.cross(yi).dot(a)<0}set(t,e,n){return this.a.copy(t),this.b.copy(e),this.c.copy(n),this}setFromPointsAndIndices(t,e,n,a){return this.a.copy(t[e]),this.b.copy(t[n]),this.c.copy(t[a]),this}setFromAttributeAndIndices(t,e,n,a){return this.a.fromBufferAttribute(t,e),this.b.fromBufferAttribute(t,n),this.c.fromBufferAttribute(t,a),this}clone(){return new this.constructor().copy(this)}copy(t){return this.a.copy(t.a),this.b.copy(t.b),this.c.copy(t.c),this}getArea(){return jn.subVectors(this.c,this.b),yi.subVectors(this.a,this.b),jn.cross(yi).length()*.5}getMidpoint(t){return t.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(t){return i.getNormal(this.a,this.b,this.c,t)}getPlane(t){return t.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(t,e){return i.getBarycoord(t,this.a,this.b,this.c,e)}getInterpolation(t,e,n,a,s){return i.getInterpolation(t,this.a,this.b,this.c,e,n,a,s)}containsPoint(t){return i.containsPoint(t,this.a,this.b,this.c)}isFrontFacing(t){return i.isFrontFacing(this.a,this.b,this.c,t)}intersectsBox(t){return t.intersectsTriangle(this)}closestPointToPoint(t,e){let n=this.a,a=this.b,s=this.c,r,o;Da.subVectors(a,n),Ua.subVectors(s,n),sh.subVectors(t,n);let c=Da.dot(sh),l=Ua.dot(sh);if(c<=0&&l<=0)return e.copy(n);rh.subVectors(t,a);let h=Da.dot(rh),u=Ua.dot(rh);if(h>=0&&u<=h)return e.copy(a);let d=c*u-h*l;if(d<=0&&c>=0&&h<=0&&c-h>0)return r=c/(c-h),e.copy(n).addScaledVector(Da,r);oh.subVectors(t,s);let f=Da.dot(oh),b=Ua.dot(oh);if(b>=0&&f<=b)return e.copy(s);let _=f*l-c*b;if(_<=0&&l>=0&&b<=0)return o=l/(l-b),e.copy(n).addScaledVector(Ua,o);let m=h*b-f*u;if(m<=0&&u-h>=0&&f-b>=0)return ku.subVectors(s,a),o=(u-h)/(u-h+(f-b)),e.copy(a).addScaledVector(ku,o);let x=1/(m+_+d);return r=_*x,o=d*x,e.copy(n).addScaledVector(Da,r).addScaledVector(Ua,o)}equals(t){return t.a.equals(this.a)&&t.b.equals(this.b)&&t.c.equals(this.c)}},Ue=class{constructor(t=new k(1/0,1/0,1/0),e=new k(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=t,this.max=e}set(t,e){return this.min.copy(t),this.max.copy(e),this}setFromArray(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e+=3)this.expandByPoint(Xn.fromArray(t,e));return this}setFromBufferAttribute(t){this.makeEmpty();for(let e=0,n=t.count;e<n;e++)this.expandByPoint(Xn.fromBufferAttribute(t,e));return this}setFromPoints(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e++)this.expandByPoint(t[e]);return this}setFromCenterAndSize(t,e){let n=Xn.copy(e).multiplyScalar(.5);return this.min.copy(t).sub(n),this.max.copy(t).add(n),this}setFromObject(t,e=!1){return this.makeEmpty(),this.expandByObject(t,e)}clone(){return new this.constructor().copy(this)}copy(t){return this.min.copy(t.min),this.max.copy(t.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(t){return this.isEmpty()?t.set(0,0,0):t.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(t){return this.isEmpty()?t.set(0,0,0):t.subVectors(this.max,this.min)}expandByPoint(t){return this.min.min(t),this.max.max(t),this}expandByVector(t){return this.min.sub(t),this.max.add(t),this}expandByScalar(t){return this.min.addScalar(-t),this.max.addScalar(t),this}expandByObject(t,e=!1){t.updateWorldMatrix(!1,!1);let n=t.geometry;if(n!==void 0){let s=n.getAttribute("position");if(e===!0&&s!==void 0&&t.isInstancedMesh!==!0&&t.isBatchedMesh!==!0)for(let r=0,o=s.count;r<o;r++)t.isMesh===!0?t.getVertexPosition(r,Xn):Xn.fromBufferAttribute(s,r),Xn.applyMatrix4(t.matrixWorld),this.expandByPoint(Xn);else t.boundingBox!==void 0?(t.boundingBox===null&&t.computeBoundingBox(),lo.copy(t.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),lo.copy(n.boundingBox)),lo.applyMatrix4(t.matrixWorld),this.union(lo)}let a=t.children;for(let s=0,r=a.length;s<r;s++)this.expandByObject(a[s],e);return this}containsPoint(t){return t.x>=this.min.x&&t.x<=this.max.x&&t.y>=this.min.y&&t.y<=this.max.y&&t.z>=this.min.z&&t.z<=this.max.z}containsBox(t){return this.min.x<=t.min.x&&t.max.x<=this.max.x&&this.min.y<=t.min.y&&t.max.y<=this.max.y&&this.min.z<=t.min.z&&t.max.z<=this.max.z}getParameter(t,e){return e.set((t.x-this.min.x)/(this.max.x-this.min.x),(t.y-this.min.y)/(this.max.y-this.min.y),(t.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(t){return t.max.x>=this.min.x&&t.min.x<=this.max.x&&t.max.y>=this.min.y&&t.min.y<=this.max.y&&t.max.z>=this.min.z&&t.min.z<=this.max.z}intersectsSphere(t){return this.clampPoint(t.center,Xn),Xn.distanceToSquared(t.center)<=t.radius*t.radius}intersectsPlane(t){let e,n;return t.normal.x>0?(e=t.normal.x*this.min.x,n=t.normal.x*this.max.x):(e=t.normal.x*this.max.x,n=t.normal.x*this.min.x),t.normal.y>0?(e+=t.normal.y*this.min.y,n+=t.normal.y*this.max.y):(e+=t.normal.y*this.max.y,n+=t.normal.y*this.min.y),t.normal.z>0?(e+=t.normal.z*this.min.z,n+=t.normal.z*this.max.z):(e+=t.normal.z*this.max.z,n+=t.normal.z*this.min.z),e<=-t.constant&&n>=-t.constant}intersectsTriangle(t){if(this.isEmpty())return!1;this.getCenter(zs),ho.subVectors(this.max,zs),Oa.subVectors(t.a,zs),Fa.subVectors(t.b,zs),Ba.subVectors(t.c,zs),zi.subVectors(Fa,Oa),Vi.subVectors(Ba,Fa),la.subVectors(Oa,Ba);let e=[0,-zi.z,zi.y,0,-Vi.z,Vi.y,0,-la.z,la.y,zi.z,0,-zi.x,Vi.z,0,-Vi.x,la.z,0,-la.x,-zi.y,zi.x,0,-Vi.y,Vi.x,0,-la.y,la.x,0];return!dh(e,Oa,Fa,Ba,ho)||(e=[1,0,0,0,1,0,0,0,1],!dh(e,Oa,Fa,Ba,ho))?!1:(uo.crossVectors(zi,Vi),e=[uo.x,uo.y,uo.z],dh(e,Oa,Fa,Ba,ho))}clampPoint(t,e){return e.copy(t).clamp(this.min,this.max)}distanceToPoint(t){return this.clampPoint(t,Xn).distanceTo(t)}getBoundingSphere(t){return this.isEmpty()?t.makeEmpty():(this.getCenter(t.center),t.radius=this.getSize(Xn).length()*.5),t}intersect(t){return this.min.max(t.min),this.max.min(t.max),this.isEmpty()&&this.makeEmpty(),this}union(t){return this.min.min(t.min),this.max.max(t.max),this}applyMatrix4(t){return this.isEmpty()?this:(vi[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(t),vi[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(t),vi[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(t),vi[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(t),vi[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(t),vi[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(t),vi[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(t),vi[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(t),this.setFromPoints(vi),this)}translate(t){return this.min.add(t),this.max.add(t),this}equals(t){return t.min.equals(this.min)&&t.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(t){return this.min.fromArray(t.min),this.max.fromArray(t.max),this}},vi=[new k,new k,new k,new k,new k,new k,new k,new k],Xn=new k,lo=new Ue,Oa=new k,Fa=new k,Ba=new k,zi=new k,Vi=new k,la=new k,zs=new k,ho=new k,uo=new k,ha=new k;Ne=new k,fo=new Ut,yb=0,mn=class extends qn{constructor(t,e,n=!1){if(super(),Array.isArray(t))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:yb++}),this.name="",this.array=t,this.itemSize=e,this.count=t!==void 0?t.length/e:0,this.normalized=n,this.usage=td,this.updateRanges=[],this.gpuType=bn,this.version=0,this._normalizationScale=t!==void 0?$c(t):void 0}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.name=t.name,this.array=new t.array.constructor(t.array),this.itemSize=t.itemSize,this.count=t.count,this.normalized=t.normalized,this.usage=t.usage,this.gpuType=t.gpuType,this._normalizationScale=t._normalizationScale,this}copyAt(t,e,n){t*=this.itemSize,n*=e.itemSize;for(let a=0,s=this.itemSize;a<s;a++)this.array[t+a]=e.array[n+a];return this}copyArray(t){return this.array.set(t),this}applyMatrix3(t){if(this.itemSize===2)for(let e=0,n=this.count;e<n;e++)fo.fromBufferAttribute(this,e),fo.applyMatrix3(t),this.setXY(e,fo.x,fo.y);else if(this.itemSize===3)for(let e=0,n=this.count;e<n;e++)Ne.fromBufferAttribute(this,e),Ne.applyMatrix3(t),this.setXYZ(e,Ne.x,Ne.y,Ne.z);return this}applyMatrix4(t){for(let e=0,n=this.count;e<n;e++)Ne.fromBufferAttribute(this,e),Ne.applyMatrix4(t),this.setXYZ(e,Ne.x,Ne.y,Ne.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)Ne.fromBufferAttribute(this,e),Ne.applyNormalMatrix(t),this.setXYZ(e,Ne.x,Ne.y,Ne.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)Ne.fromBufferAttribute(this,e),Ne.transformDirection(t),this.setXYZ(e,Ne.x,Ne.y,Ne.z);return this}set(t,e=0){return this.array.set(t,e),this}getComponent(t,e){let n=this.array[t*this.itemSize+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.array[t*this.itemSize+e]=n,this}getX(t){let e=this.array[t*this.itemSize];return this.normalized&&(e=this._denormalize(e)),e}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize]=e,this}getY(t){let e=this.array[t*this.itemSize+1];return this.normalized&&(e=this._denormalize(e)),e}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+1]=e,this}getZ(t){let e=this.array[t*this.itemSize+2];return this.normalized&&(e=this._denormalize(e)),e}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+2]=e,this}getW(t){let e=this.array[t*this.itemSize+3];return this.normalized&&(e=this._denormalize(e)),e}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+3]=e,this}setXY(t,e,n){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.array[t+0]=e,this.array[t+1]=n,this}setXYZ(t,e,n,a){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=a,this}setXYZW(t,e,n,a,s){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a),s=this._normalize(s)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=a,this.array[t+3]=s,this}onUpload(t){return this.onUploadCallback=t,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let t={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return t.name=this.name,t.usage=this.usage,t.gpuType=this.gpuType,t}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(t){let e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):ad(t,this.array)}_normalize(t){let e=this._normalizationScale;return e!==void 0?Math.round(t*e):sd(t,this.array)}},tr=class extends mn{constructor(t,e,n){super(new Uint16Array(t),e,n)}},er=class extends mn{constructor(t,e,n){super(new Uint32Array(t),e,n)}},me=class extends mn{constructor(t,e,n){super(new Float32Array(t),e,n)}},_b=new Ue,Vs=new k,uh=new k,We=class{constructor(t=new k,e=-1){this.isSphere=!0,this.center=t,this.radius=e}set(t,e){return this.center.copy(t),this.radius=e,this}setFromPoints(t,e){let n=this.center;e!==void 0?n.copy(e):_b.setFromPoints(t).getCenter(n);let a=0;for(let s=0,r=t.length;s<r;s++)a=Math.max(a,n.distanceToSquared(t[s]));return this.radius=Math.sqrt(a),this}copy(t){return this.center.copy(t.center),this.radius=t.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(t){return t.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(t){return t.distanceTo(this.center)-this.radius}intersectsSphere(t){let e=this.radius+t.radius;return t.center.distanceToSquared(this.center)<=e*e}intersectsBox(t){return t.intersectsSphere(this)}intersectsPlane(t){return Math.abs(t.distanceToPoint(this.center))<=this.radius}clampPoint(t,e){let n=this.center.distanceToSquared(t);return e.copy(t),n>this.radius*this.radius&&(e.sub(this.center).normalize(),e.multiplyScalar(this.radius).add(this.center)),e}getBoundingBox(t){return this.isEmpty()?(t.makeEmpty(),t):(t.set(this.center,this.center),t.expandByScalar(this.radius),t)}applyMatrix4(t){return this.center.applyMatrix4(t),this.radius=this.radius*t.getMaxScaleOnAxis(),this}translate(t){return this.center.add(t),this}expandByPoint(t){if(this.isEmpty())return this.center.copy(t),this.radius=0,this;Vs.subVectors(t,this.center);let e=Vs.lengthSq();if(e>this.radius*this.radius){let n=Math.sqrt(e),a=(n-this.radius)*.5;this.center.addScaledVector(Vs,a/n),this.radius+=a}return this}union(t){return t.isEmpty()?this:this.isEmpty()?(this.copy(t),this):(this.center.equals(t.center)===!0?this.radius=Math.max(this.radius,t.radius):(uh.subVectors(t.center,this.center).setLength(t.radius),this.expandByPoint(Vs.copy(t.center).add(uh)),this.expandByPoint(Vs.copy(t.center).sub(uh))),this)}equals(t){return t.center.equals(this.center)&&t.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(t){return this.radius=t.radius,this.center.fromArray(t.center),this}},vb=0,Un=new se,fh=new Oe,ka=new k,Tn=new Ue,Hs=new Ue,Ge=new k,Le=class i extends qn{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:vb++}),this.uuid=Ji(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(t){return Array.isArray(t)?this.index=new(Xg(t)?er:tr)(t,1):this.index=t,this}setIndirect(t,e=0){return this.indirect=t,this.indirectOffset=e,this}getIndirect(){return this.indirect}getAttribute(t){return this.attributes[t]}setAttribute(t,e){return this.attributes[t]=e,this}deleteAttribute(t){return delete this.attributes[t],this}hasAttribute(t){return this.attributes[t]!==void 0}addGroup(t,e,n=0){this.groups.push({start:t,count:e,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(t,e){this.drawRange.start=t,this.drawRange.count=e}applyMatrix4(t){let e=this.attributes.position;e!==void 0&&(e.applyMatrix4(t),e.needsUpdate=!0);let n=this.attributes.normal;if(n!==void 0){let s=new Bt().getNormalMatrix(t);n.applyNormalMatrix(s),n.needsUpdate=!0}let a=this.attributes.tangent;return a!==void 0&&(a.transformDirection(t),a.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(t){return Un.makeRotationFromQuaternion(t),this.applyMatrix4(Un),this}rotateX(t){return Un.makeRotationX(t),this.applyMatrix4(Un),this}rotateY(t){return Un.makeRotationY(t),this.applyMatrix4(Un),this}rotateZ(t){return Un.makeRotationZ(t),this.applyMatrix4(Un),this}translate(t,e,n){return Un.makeTranslation(t,e,n),this.applyMatrix4(Un),this}scale(t,e,n){return Un.makeScale(t,e,n),this.applyMatrix4(Un),this}lookAt(t){return fh.lookAt(t),fh.updateMatrix(),this.applyMatrix4(fh.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(ka).negate(),this.translate(ka.x,ka.y,ka.z),this}setFromPoints(t){let e=this.getAttribute("position");if(e===void 0){let n=[];for(let a=0,s=t.length;a<s;a++){let r=t[a];n.push(r.x,r.y,r.z||0)}this.setAttribute("position",new me(n,3))}else{let n=Math.min(t.length,e.count);for(let a=0;a<n;a++){let s=t[a];e.setXYZ(a,s.x,s.y,s.z||0)}t.length>e.count&&Dt("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),e.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ue);let t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){Ft("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new k(-1/0,-1/0,-1/0),new k(1/0,1/0,1/0));return}if(t!==void 0){if(this.boundingBox.setFromBufferAttribute(t),e)for(let n=0,a=e.length;n<a;n++){let s=e[n];Tn.setFromBufferAttribute(s),this.morphTargetsRelative?(Ge.addVectors(this.boundingBox.min,Tn.min),this.boundingBox.expandByPoint(Ge),Ge.addVectors(this.boundingBox.max,Tn.max),this.boundingBox.expandByPoint(Ge)):(this.boundingBox.expandByPoint(Tn.min),this.boundingBox.expandByPoint(Tn.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&Ft('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new We);let t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){Ft("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new k,1/0);return}if(t){let n=this.boundingSphere.center;if(Tn.setFromBufferAttribute(t),e)for(let s=0,r=e.length;s<r;s++){let o=e[s];Hs.setFromBufferAttribute(o),this.morphTargetsRelative?(Ge.addVectors(Tn.min,Hs.min),Tn.expandByPoint(Ge),Ge.addVectors(Tn.max,Hs.max),Tn.expandByPoint(Ge)):(Tn.expandByPoint(Hs.min),Tn.expandByPoint(Hs.max))}Tn.getCenter(n);let a=0;for(let s=0,r=t.count;s<r;s++)Ge.fromBufferAttribute(t,s),a=Math.max(a,n.distanceToSquared(Ge));if(e)for(let s=0,r=e.length;s<r;s++){let o=e[s],c=this.morphTargetsRelative;for(let l=0,h=o.count;l<h;l++)Ge.fromBufferAttribute(o,l),c&&(ka.fromBufferAttribute(t,l),Ge.add(ka)),a=Math.max(a,n.distanceToSquared(Ge))}this.boundingSphere.radius=Math.sqrt(a),isNaN(this.boundingSphere.radius)&&Ft('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let t=this.index,e=this.attributes;if(t===null||e.position===void 0||e.normal===void 0||e.uv===void 0){Ft("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let n=e.position,a=e.normal,s=e.uv,r=this.getAttribute("tangent");(r===void 0||r.count!==n.count)&&(r=new mn(new Float32Array(4*n.count),4),this.setAttribute("tangent",r));let o=[],c=[],l=new Uint8Array(n.count);for(let E=0;E<n.count;E++)o[E]=new k,c[E]=new k;let h=new k,u=new k,d=new k,f=new Ut,b=new Ut,_=new Ut,m=new k,x=new k;function v(E,A,I){l[E]=l[A]=l[I]=1,h.fromBufferAttribute(n,E),u.fromBufferAttribute(n,A),d.fromBufferAttribute(n,I),f.fromBufferAttribute(s,E),b.fromBufferAttribute(s,A),_.fromBufferAttribute(s,I),u.sub(h),d.sub(h),b.sub(f),_.sub(f);let C=1/(b.x*_.y-_.x*b.y);isFinite(C)&&(m.copy(u).multiplyScalar(_.y).addScaledVector(d,-b.y).multiplyScalar(C),x.copy(d).multiplyScalar(b.x).addScaledVector(u,-_.x).multiplyScalar(C),o[E].add(m),o[A].add(m),o[I].add(m),c[E].add(x),c[A].add(x),c[I].add(x))}let w=this.groups;w.length===0&&(w=[{start:0,count:t.count}]);for(let E=0,A=w.length;E<A;++E){let I=w[E],C=I.start,P=I.count;for(let N=C,U=C+P;N<U;N+=3)v(t.getX(N+0),t.getX(N+1),t.getX(N+2))}let p=new k,y=new k,S=new k,g=new k;function M(E){S.fromBufferAttribute(a,E),g.copy(S);let A=o[E];p.copy(A),p.sub(S.multiplyScalar(S.dot(A))).normalize(),y.crossVectors(g,A);let C=y.dot(c[E])<0?-1:1;r.setXYZW(E,p.x,p.y,p.z,C)}for(let E=0,A=n.count;E<A;++E)l[E]&&M(E);this._transformed=!0}computeVertexNormals(){let t=this.index,e=this.getAttribute("position");if(e!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==e.count)n=new mn(new Float32Array(e.count*3),3),this.setAttribute("normal",n);else for(let d=0,f=n.count;d<f;d++)n.setXYZ(d,0,0,0);let a=new k,s=new k,r=new k,o=new k,c=new k,l=new k,h=new k,u=new k;if(t)for(let d=0,f=t.count;d<f;d+=3){let b=t.getX(d+0),_=t.getX(d+1),m=t.getX(d+2);a.fromBufferAttribute(e,b),s.fromBufferAttribute(e,_),r.fromBufferAttribute(e,m),h.subVectors(r,s),u.subVectors(a,s),h.cross(u),o.fromBufferAttribute(n,b),c.fromBufferAttribute(n,_),l.fromBufferAttribute(n,m),o.add(h),c.add(h),l.add(h),n.setXYZ(b,o.x,o.y,o.z),n.setXYZ(_,c.x,c.y,c.z),n.setXYZ(m,l.x,l.y,l.z)}else for(let d=0,f=e.count;d<f;d+=3)a.fromBufferAttribute(e,d+0),s.fromBufferAttribute(e,d+1),r.fromBufferAttribute(e,d+2),h.subVectors(r,s),u.subVectors(a,s),h.cross(u),n.setXYZ(d+0,h.x,h.y,h.z),n.setXYZ(d+1,h.x,h.y,h.z),n.setXYZ(d+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){let t=this.attributes.normal;for(let e=0,n=t.count;e<n;e++)Ge.fromBufferAttribute(t,e),Ge.normalize(),t.setXYZ(e,Ge.x,Ge.y,Ge.z)}toNonIndexed(){function t(o,c){let l=o.array,h=o.itemSize,u=o.normalized,d=new l.constructor(c.length*h),f=0,b=0;for(let _=0,m=c.length;_<m;_++){o.isInterleavedBufferAttribute?f=c[_]*o.data.stride+o.offset:f=c[_]*h;for(let x=0;x<h;x++)d[b++]=l[f++]}return new mn(d,h,u)}if(this.index===null)return Dt("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let e=new i,n=this.index.array,a=this.attributes;for(let o in a){let c=a[o],l=t(c,n);e.setAttribute(o,l)}let s=this.morphAttributes;for(let o in s){let c=[],l=s[o];for(let h=0,u=l.length;h<u;h++){let d=l[h],f=t(d,n);c.push(f)}e.morphAttributes[o]=c}e.morphTargetsRelative=this.morphTargetsRelative;let r=this.groups;for(let o=0,c=r.length;o<c;o++){let l=r[o];e.addGroup(l.start,l.count,l.materialIndex)}return e}toJSON(){let t={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(t.uuid=this.uuid,t.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,t.name=this.name,Object.keys(this.userData).length>0&&(t.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let c=this.parameters;for(let l in c)c[l]!==void 0&&(t[l]=c[l]);return t}t.data={attributes:{}};let e=this.index;e!==null&&(t.data.index={type:e.array.constructor.name,array:Array.prototype.slice.call(e.array)});let n=this.attributes;for(let c in n){let l=n[c];t.data.attributes[c]=l.toJSON(t.data)}let a={},s=!1;for(let c in this.morphAttributes){let l=this.morphAttributes[c],h=[];for(let u=0,d=l.length;u<d;u++){let f=l[u];h.push(f.toJSON(t.data))}h.length>0&&(a[c]=h,s=!0)}s&&(t.data.morphAttributes=a,t.data.morphTargetsRelative=this.morphTargetsRelative);let r=this.groups;r.length>0&&(t.data.groups=JSON.parse(JSON.stringify(r)));let o=this.boundingSphere;return o!==null&&(t.data.boundingSphere=o.toJSON()),t}clone(){return new this.constructor().copy(this)}copy(t){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let e={};this.name=t.name;let n=t.index;n!==null&&this.setIndex(n.clone());let a=t.attributes;for(let l in a){let h=a[l];this.setAttribute(l,h.clone(e))}let s=t.morphAttributes;for(let l in s){let h=[],u=s[l];for(let d=0,f=u.length;d<f;d++)h.push(u[d].clone(e));this.morphAttributes[l]=h}this.morphTargetsRelative=t.morphTargetsRelative;let r=t.groups;for(let l=0,h=r.length;l<h;l++){let u=r[l];this.addGroup(u.start,u.count,u.materialIndex)}let o=t.boundingBox;o!==null&&(this.boundingBox=o.clone());let c=t.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=t.drawRange.start,this.drawRange.count=t.drawRange.count,this.userData=t.userData,this._transformed=t._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}},Jo=class{constructor(t,e){this.isInterleavedBuffer=!0,this.array=t,this.stride=e,this.count=t!==void 0?t.length/e:0,this.usage=td,this.updateRanges=[],this.version=0,this.uuid=Ji()}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.array=new t.array.constructor(t.array),this.count=t.count,this.stride=t.stride,this.usage=t.usage,this}copyAt(t,e,n){t*=this.stride,n*=e.stride;for(let a=0,s=this.stride;a<s;a++)this.array[t+a]=e.array[n+a];return this}set(t,e=0){return this.array.set(t,e),this}clone(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});let e=zu(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=this.array.slice(0).buffer);let n=new this.array.constructor(t.arrayBuffers[e]),a=new this.constructor(n,this.stride);return a.setUsage(this.usage),a}onUpload(t){return this.onUploadCallback=t,this}toJSON(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});let e=zu(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=Array.from(new Uint32Array(this.array.slice(0).buffer)));let n={uuid:this.uuid,buffer:e,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}};un=new k,Yn=class i{constructor(t,e,n,a=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=t,this.itemSize=e,this.offset=n,this.normalized=a,this._normalizationScale=t!==void 0?$c(t.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(t){this.data.needsUpdate=t}applyMatrix4(t){for(let e=0,n=this.data.count;e<n;e++)un.fromBufferAttribute(this,e),un.applyMatrix4(t),this.setXYZ(e,un.x,un.y,un.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)un.fromBufferAttribute(this,e),un.applyNormalMatrix(t),this.setXYZ(e,un.x,un.y,un.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)un.fromBufferAttribute(this,e),un.transformDirection(t),this.setXYZ(e,un.x,un.y,un.z);return this}getComponent(t,e){let n=this.array[t*this.data.stride+this.offset+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.data.array[t*this.data.stride+this.offset+e]=n,this}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset]=e,this}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+1]=e,this}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+2]=e,this}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+3]=e,this}getX(t){let e=this.data.array[t*this.data.stride+this.offset];return this.normalized&&(e=this._denormalize(e)),e}getY(t){let e=this.data.array[t*this.data.stride+this.offset+1];return this.normalized&&(e=this._denormalize(e)),e}getZ(t){let e=this.data.array[t*this.data.stride+this.offset+2];return this.normalized&&(e=this._denormalize(e)),e}getW(t){let e=this.data.array[t*this.data.stride+this.offset+3];return this.normalized&&(e=this._denormalize(e)),e}setXY(t,e,n){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.data.array[t+0]=e,this.data.array[t+1]=n,this}setXYZ(t,e,n,a){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=a,this}setXYZW(t,e,n,a,s){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a),s=this._normalize(s)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=a,this.data.array[t+3]=s,this}clone(t){if(t===void 0){Zs("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");let e=[];for(let n=0;n<this.count;n++){let a=n*this.data.stride+this.offset;for(let s=0;s<this.itemSize;s++)e.push(this.data.array[a+s])}return new mn(new this.array.constructor(e),this.itemSize,this.normalized)}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.clone(t)),new i(t.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(t){if(t===void 0){Zs("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");let e=[];for(let n=0;n<this.count;n++){let a=n*this.data.stride+this.offset;for(let s=0;s<this.itemSize;s++)e.push(this.data.array[a+s])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:e,normalized:this.normalized}}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.toJSON(t)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(t){let e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):ad(t,this.data.array)}_normalize(t){let e=this._normalizationScale;return e!==void 0?Math.round(t*e):sd(t,this.data.array)}},ph=new k,Mb=new k,Sb=new Bt,fn=class{constructor(t=new k(1,0,0),e=0){this.isPlane=!0,this.normal=t,this.constant=e}set(t,e){return this.normal.copy(t),this.constant=e,this}setComponents(t,e,n,a){return this.normal.set(t,e,n),this.constant=a,this}setFromNormalAndCoplanarPoint(t,e){return this.normal.copy(t),this.constant=-e.dot(this.normal),this}setFromCoplanarPoints(t,e,n){let a=ph.subVectors(n,e).cross(Mb.subVectors(t,e)).normalize();return this.setFromNormalAndCoplanarPoint(a,t),this}copy(t){return this.normal.copy(t.normal),this.constant=t.constant,this}normalize(){let t=1/this.normal.length();return this.normal.multiplyScalar(t),this.constant*=t,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(t){return this.normal.dot(t)+this.constant}distanceToSphere(t){return this.distanceToPoint(t.center)-t.radius}projectPoint(t,e){return e.copy(t).addScaledVector(this.normal,-this.distanceToPoint(t))}intersectLine(t,e,n=!0){let a=t.delta(ph),s=this.normal.dot(a);if(s===0)return this.distanceToPoint(t.start)===0?e.copy(t.start):null;let r=-(t.start.dot(this.normal)+this.constant)/s;return n===!0&&(r<0||r>1)?null:e.copy(t.start).addScaledVector(a,r)}intersectsLine(t){let e=this.distanceToPoint(t.start),n=this.distanceToPoint(t.end);return e<0&&n>0||n<0&&e>0}intersectsBox(t){return t.intersectsPlane(this)}intersectsSphere(t){return t.intersectsPlane(this)}coplanarPoint(t){return t.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(t,e){let n=e||Sb.getNormalMatrix(t),a=this.coplanarPoint(ph).applyMatrix4(t),s=this.normal.applyMatrix3(n).normalize();return this.constant=-a.dot(s),this}translate(t){return this.constant-=t.dot(this.normal),this}equals(t){return t.normal.equals(this.normal)&&t.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(t){return this.normal.fromArray(t.normal),this.constant=t.constant,this}},wb=0,si=class extends qn{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:wb++}),this.uuid=Ji(),this.name="",this.type="Material",this.blending=rs,this.side=oi,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Fh,this.blendDst=Bh,this.blendEquation=xa,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new Ht(0,0,0),this.blendAlpha=0,this.depthFunc=Xa,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Ff,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=Uo,this.stencilZFail=Uo,this.stencilZPass=Uo,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(t){this._alphaTest>0!=t>0&&this.version++,this._alphaTest=t}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(t){if(t!==void 0)for(let e in t){let n=t[e];if(n===void 0){Dt(`Material: parameter '${e}' has value of undefined.`);continue}let a=this[e];if(a===void 0){Dt(`Material: '${e}' is not a property of THREE.${this.type}.`);continue}a&&a.isColor?a.set(n):a&&a.isVector2&&n&&n.isVector2||a&&a.isEuler&&n&&n.isEuler||a&&a.isVector3&&n&&n.isVector3?a.copy(n):this[e]=n}}toJSON(t){let e=t===void 0||typeof t=="string";e&&(t={textures:{},images:{}});let n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(t).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(t).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(t).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(t).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(t).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(t).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(t).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(t).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(t).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(t).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(t).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(t).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(t).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(t).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(t).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(t).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(t).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(t).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(t).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(t).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(t).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(t).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(t).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(t).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(t).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(t).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(t).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(s=>s.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function a(s){let r=[];for(let o in s){let c=s[o];delete c.metadata,r.push(c)}return r}if(e){let s=a(t.textures),r=a(t.images);s.length>0&&(n.textures=s),r.length>0&&(n.images=r)}return n}fromJSON(t,e){if(t.uuid!==void 0&&(this.uuid=t.uuid),t.name!==void 0&&(this.name=t.name),t.color!==void 0&&this.color!==void 0&&this.color.setHex(t.color),t.roughness!==void 0&&(this.roughness=t.roughness),t.metalness!==void 0&&(this.metalness=t.metalness),t.sheen!==void 0&&(this.sheen=t.sheen),t.sheenColor!==void 0&&(this.sheenColor=new Ht().setHex(t.sheenColor)),t.sheenRoughness!==void 0&&(this.sheenRoughness=t.sheenRoughness),t.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(t.emissive),t.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(t.specular),t.specularIntensity!==void 0&&(this.specularIntensity=t.specularIntensity),t.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(t.specularColor),t.shininess!==void 0&&(this.shininess=t.shininess),t.clearcoat!==void 0&&(this.clearcoat=t.clearcoat),t.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=t.clearcoatRoughness),t.diffuseRoughness!==void 0&&(this.diffuseRoughness=t.diffuseRoughness),t.dispersion!==void 0&&(this.dispersion=t.dispersion),t.retroreflectivity!==void 0&&(this.retroreflectivity=t.retroreflectivity),t.iridescence!==void 0&&(this.iridescence=t.iridescence),t.iridescenceIOR!==void 0&&(this.iridescenceIOR=t.iridescenceIOR),t.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessMinimum),t.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=t.iridescenceThicknessMaximum),t.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=t.iridescenceThicknessRange[1]),t.transmission!==void 0&&(this.transmission=t.transmission),t.thickness!==void 0&&(this.thickness=t.thickness),t.attenuationDistance!==void 0&&(this.attenuationDistance=t.attenuationDistance),t.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(t.attenuationColor),t.anisotropy!==void 0&&(this.anisotropy=t.anisotropy),t.anisotropyRotation!==void 0&&(this.anisotropyRotation=t.anisotropyRotation),t.fog!==void 0&&(this.fog=t.fog),t.flatShading!==void 0&&(this.flatShading=t.flatShading),t.blending!==void 0&&(this.blending=t.blending),t.combine!==void 0&&(this.combine=t.combine),t.side!==void 0&&(this.side=t.side),t.shadowSide!==void 0&&(this.shadowSide=t.shadowSide),t.opacity!==void 0&&(this.opacity=t.opacity),t.transparent!==void 0&&(this.transparent=t.transparent),t.alphaTest!==void 0&&(this.alphaTest=t.alphaTest),t.alphaHash!==void 0&&(this.alphaHash=t.alphaHash),t.depthFunc!==void 0&&(this.depthFunc=t.depthFunc),t.depthTest!==void 0&&(this.depthTest=t.depthTest),t.depthWrite!==void 0&&(this.depthWrite=t.depthWrite),t.colorWrite!==void 0&&(this.colorWrite=t.colorWrite),t.clippingPlanes!==void 0&&(this.clippingPlanes=t.clippingPlanes.map(n=>new fn().fromJSON(n))),t.clipIntersection!==void 0&&(this.clipIntersection=t.clipIntersection),t.clipShadows!==void 0&&(this.clipShadows=t.clipShadows),t.depthPacking!==void 0&&(this.depthPacking=t.depthPacking),t.blendSrc!==void 0&&(this.blendSrc=t.blendSrc),t.blendDst!==void 0&&(this.blendDst=t.blendDst),t.blendEquation!==void 0&&(this.blendEquation=t.blendEquation),t.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=t.blendSrcAlpha),t.blendDstAlpha!==void 0&&(this.blendDstAlpha=t.blendDstAlpha),t.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=t.blendEquationAlpha),t.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(t.blendColor),t.blendAlpha!==void 0&&(this.blendAlpha=t.blendAlpha),t.stencilWriteMask!==void 0&&(this.stencilWriteMask=t.stencilWriteMask),t.stencilFunc!==void 0&&(this.stencilFunc=t.stencilFunc),t.stencilRef!==void 0&&(this.stencilRef=t.stencilRef),t.stencilFuncMask!==void 0&&(this.stencilFuncMask=t.stencilFuncMask),t.stencilFail!==void 0&&(this.stencilFail=t.stencilFail),t.stencilZFail!==void 0&&(this.stencilZFail=t.stencilZFail),t.stencilZPass!==void 0&&(this.stencilZPass=t.stencilZPass),t.stencilWrite!==void 0&&(this.stencilWrite=t.stencilWrite),t.wireframe!==void 0&&(this.wireframe=t.wireframe),t.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=t.wireframeLinewidth),t.wireframeLinecap!==void 0&&(this.wireframeLinecap=t.wireframeLinecap),t.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=t.wireframeLinejoin),t.rotation!==void 0&&(this.rotation=t.rotation),t.linewidth!==void 0&&(this.linewidth=t.linewidth),t.linecap!==void 0&&(this.linecap=t.linecap),t.linejoin!==void 0&&(this.linejoin=t.linejoin),t.dashSize!==void 0&&(this.dashSize=t.dashSize),t.gapSize!==void 0&&(this.gapSize=t.gapSize),t.scale!==void 0&&(this.scale=t.scale),t.polygonOffset!==void 0&&(this.polygonOffset=t.polygonOffset),t.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=t.polygonOffsetFactor),t.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=t.polygonOffsetUnits),t.dithering!==void 0&&(this.dithering=t.dithering),t.alphaToCoverage!==void 0&&(this.alphaToCoverage=t.alphaToCoverage),t.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=t.premultipliedAlpha),t.forceSinglePass!==void 0&&(this.forceSinglePass=t.forceSinglePass),t.allowOverride!==void 0&&(this.allowOverride=t.allowOverride),t.visible!==void 0&&(this.visible=t.visible),t.toneMapped!==void 0&&(this.toneMapped=t.toneMapped),t.userData!==void 0&&(this.userData=t.userData),t.vertexColors!==void 0&&(typeof t.vertexColors=="number"?this.vertexColors=t.vertexColors>0:this.vertexColors=t.vertexColors),t.size!==void 0&&(this.size=t.size),t.sizeAttenuation!==void 0&&(this.sizeAttenuation=t.sizeAttenuation),t.map!==void 0&&(this.map=e[t.map]||null),t.matcap!==void 0&&(this.matcap=e[t.matcap]||null),t.alphaMap!==void 0&&(this.alphaMap=e[t.alphaMap]||null),t.bumpMap!==void 0&&(this.bumpMap=e[t.bumpMap]||null),t.bumpScale!==void 0&&(this.bumpScale=t.bumpScale),t.normalMap!==void 0&&(this.normalMap=e[t.normalMap]||null),t.normalMapType!==void 0&&(this.normalMapType=t.normalMapType),t.normalScale!==void 0){let n=t.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Ut().fromArray(n)}return t.displacementMap!==void 0&&(this.displacementMap=e[t.displacementMap]||null),t.displacementScale!==void 0&&(this.displacementScale=t.displacementScale),t.displacementBias!==void 0&&(this.displacementBias=t.displacementBias),t.roughnessMap!==void 0&&(this.roughnessMap=e[t.roughnessMap]||null),t.metalnessMap!==void 0&&(this.metalnessMap=e[t.metalnessMap]||null),t.emissiveMap!==void 0&&(this.emissiveMap=e[t.emissiveMap]||null),t.emissiveIntensity!==void 0&&(this.emissiveIntensity=t.emissiveIntensity),t.specularMap!==void 0&&(this.specularMap=e[t.specularMap]||null),t.specularIntensityMap!==void 0&&(this.specularIntensityMap=e[t.specularIntensityMap]||null),t.specularColorMap!==void 0&&(this.specularColorMap=e[t.specularColorMap]||null),t.envMap!==void 0&&(this.envMap=e[t.envMap]||null),t.envMapRotation!==void 0&&this.envMapRotation.fromArray(t.envMapRotation),t.envMapIntensity!==void 0&&(this.envMapIntensity=t.envMapIntensity),t.reflectivity!==void 0&&(this.reflectivity=t.reflectivity),t.refractionRatio!==void 0&&(this.refractionRatio=t.refractionRatio),t.lightMap!==void 0&&(this.lightMap=e[t.lightMap]||null),t.lightMapIntensity!==void 0&&(this.lightMapIntensity=t.lightMapIntensity),t.aoMap!==void 0&&(this.aoMap=e[t.aoMap]||null),t.aoMapIntensity!==void 0&&(this.aoMapIntensity=t.aoMapIntensity),t.gradientMap!==void 0&&(this.gradientMap=e[t.gradientMap]||null),t.clearcoatMap!==void 0&&(this.clearcoatMap=e[t.clearcoatMap]||null),t.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=e[t.clearcoatRoughnessMap]||null),t.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=e[t.clearcoatNormalMap]||null),t.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Ut().fromArray(t.clearcoatNormalScale)),t.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=e[t.diffuseRoughnessMap]||null),t.iridescenceMap!==void 0&&(this.iridescenceMap=e[t.iridescenceMap]||null),t.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=e[t.iridescenceThicknessMap]||null),t.transmissionMap!==void 0&&(this.transmissionMap=e[t.transmissionMap]||null),t.thicknessMap!==void 0&&(this.thicknessMap=e[t.thicknessMap]||null),t.anisotropyMap!==void 0&&(this.anisotropyMap=e[t.anisotropyMap]||null),t.sheenColorMap!==void 0&&(this.sheenColorMap=e[t.sheenColorMap]||null),t.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=e[t.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(t){this.name=t.name,this.blending=t.blending,this.side=t.side,this.vertexColors=t.vertexColors,this.opacity=t.opacity,this.transparent=t.transparent,this.blendSrc=t.blendSrc,this.blendDst=t.blendDst,this.blendEquation=t.blendEquation,this.blendSrcAlpha=t.blendSrcAlpha,this.blendDstAlpha=t.blendDstAlpha,this.blendEquationAlpha=t.blendEquationAlpha,this.blendColor.copy(t.blendColor),this.blendAlpha=t.blendAlpha,this.depthFunc=t.depthFunc,this.depthTest=t.depthTest,this.depthWrite=t.depthWrite,this.stencilWriteMask=t.stencilWriteMask,this.stencilFunc=t.stencilFunc,this.stencilRef=t.stencilRef,this.stencilFuncMask=t.stencilFuncMask,this.stencilFail=t.stencilFail,this.stencilZFail=t.stencilZFail,this.stencilZPass=t.stencilZPass,this.stencilWrite=t.stencilWrite;let e=t.clippingPlanes,n=null;if(e!==null){let a=e.length;n=new Array(a);for(let s=0;s!==a;++s)n[s]=e[s].clone()}return this.clippingPlanes=n,this.clipIntersection=t.clipIntersection,this.clipShadows=t.clipShadows,this.shadowSide=t.shadowSide,this.colorWrite=t.colorWrite,this.precision=t.precision,this.polygonOffset=t.polygonOffset,this.polygonOffsetFactor=t.polygonOffsetFactor,this.polygonOffsetUnits=t.polygonOffsetUnits,this.dithering=t.dithering,this.alphaTest=t.alphaTest,this.alphaHash=t.alphaHash,this.alphaToCoverage=t.alphaToCoverage,this.premultipliedAlpha=t.premultipliedAlpha,this.forceSinglePass=t.forceSinglePass,this.allowOverride=t.allowOverride,this.visible=t.visible,this.toneMapped=t.toneMapped,this.userData=JSON.parse(JSON.stringify(t.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(t){t===!0&&this.version++}},Mi=new k,mh=new k,po=new k,mo=new k,Jn=class{constructor(t=new k,e=new k(0,0,-1)){this.origin=t,this.direction=e}set(t,e){return this.origin.copy(t),this.direction.copy(e),this}copy(t){return this.origin.copy(t.origin),this.direction.copy(t.direction),this}at(t,e){return e.copy(this.origin).addScaledVector(this.direction,t)}lookAt(t){return this.direction.copy(t).sub(this.origin).normalize(),this}recast(t){return this.origin.copy(this.at(t,Mi)),this}closestPointToPoint(t,e){e.subVectors(t,this.origin);let n=e.dot(this.direction);return n<0?e.copy(this.origin):e.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(t){return Math.sqrt(this.distanceSqToPoint(t))}distanceSqToPoint(t){let e=Mi.subVectors(t,this.origin).dot(this.direction);return e<0?this.origin.distanceToSquared(t):(Mi.copy(this.origin).addScaledVector(this.direction,e),Mi.distanceToSquared(t))}distanceSqToSegment(t,e,n,a){mh.copy(t).add(e).multiplyScalar(.5),po.copy(e).sub(t).normalize(),mo.copy(this.origin).sub(mh);let s=t.distanceTo(e)*.5,r=-this.direction.dot(po),o=mo.dot(this.direction),c=-mo.dot(po),l=mo.lengthSq(),h=Math.abs(1-r*r),u,d,f,b;if(h>0)if(u=r*c-o,d=r*o-c,b=s*h,u>=0)if(d>=-b)if(d<=b){let _=1/h;u*=_,d*=_,f=u*(u+r*d+2*o)+d*(r*u+d+2*c)+l}else d=s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;else d=-s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;else d<=-b?(u=Math.max(0,-(-r*s+o)),d=u>0?-s:Math.min(Math.max(-s,-c),s),f=-u*u+d*(d+2*c)+l):d<=b?(u=0,d=Math.min(Math.max(-s,-c),s),f=d*(d+2*c)+l):(u=Math.max(0,-(r*s+o)),d=u>0?s:Math.min(Math.max(-s,-c),s),f=-u*u+d*(d+2*c)+l);else d=r>0?-s:s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;return n&&n.copy(this.origin).addScaledVector(this.direction,u),a&&a.copy(mh).addScaledVector(po,d),f}intersectSphere(t,e){if(t.radius<0)return null;Mi.subVectors(t.center,this.origin);let n=Mi.dot(this.direction),a=Mi.dot(Mi)-n*n,s=t.radius*t.radius;if(a>s)return null;let r=Math.sqrt(s-a),o=n-r,c=n+r;return c<0?null:o<0?this.at(c,e):this.at(o,e)}intersectsSphere(t){return t.radius<0?!1:this.distanceSqToPoint(t.center)<=t.radius*t.radius}distanceToPlane(t){let e=t.normal.dot(this.direction);if(e===0)return t.distanceToPoint(this.origin)===0?0:null;let n=-(this.origin.dot(t.normal)+t.constant)/e;return n>=0?n:null}intersectPlane(t,e){let n=this.distanceToPlane(t);return n===null?null:this.at(n,e)}intersectsPlane(t){let e=t.distanceToPoint(this.origin);return e===0||t.normal.dot(this.direction)*e<0}intersectBox(t,e){let n,a,s,r,o,c,l=1/this.direction.x,h=1/this.direction.y,u=1/this.direction.z,d=this.origin;return l>=0?(n=(t.min.x-d.x)*l,a=(t.max.x-d.x)*l):(n=(t.max.x-d.x)*l,a=(t.min.x-d.x)*l),h>=0?(s=(t.min.y-d.y)*h,r=(t.max.y-d.y)*h):(s=(t.max.y-d.y)*h,r=(t.min.y-d.y)*h),n>r||s>a||((s>n||isNaN(n))&&(n=s),(r<a||isNaN(a))&&(a=r),u>=0?(o=(t.min.z-d.z)*u,c=(t.max.z-d.z)*u):(o=(t.max.z-d.z)*u,c=(t.min.z-d.z)*u),n>c||o>a)||((o>n||n!==n)&&(n=o),(c<a||a!==a)&&(a=c),a<0)?null:this.at(n>=0?n:a,e)}intersectsBox(t){return this.intersectBox(t,Mi)!==null}intersectTriangle(t,e,n,a,s){let r=this.origin,o=this.direction,c=o.x,l=o.y,h=o.z,u=t.x-r.x,d=t.y-r.y,f=t.z-r.z,b=e.x-r.x,_=e.y-r.y,m=e.z-r.z,x=n.x-r.x,v=n.y-r.y,w=n.z-r.z,p=Math.abs(c),y=Math.abs(l),S=Math.abs(h),g,M,E,A,I,C,P,N,U,z,F,K;if(p>=y&&p>=S?(E=c,C=u,U=b,K=x,c>=0?(g=l,M=h,A=d,I=f,P=_,N=m,z=v,F=w):(g=h,M=l,A=f,I=d,P=m,N=_,z=w,F=v)):y>=S?(E=l,C=d,U=_,K=v,l>=0?(g=h,M=c,A=f,I=u,P=m,N=b,z=w,F=x):(g=c,M=h,A=u,I=f,P=b,N=m,z=x,F=w)):(E=h,C=f,U=m,K=w,h>=0?(g=c,M=l,A=u,I=d,P=b,N=_,z=x,F=v):(g=l,M=c,A=d,I=u,P=_,N=b,z=v,F=x)),E===0)return null;let H=g/E,J=M/E,tt=1/E,ft=A-H*C,Ct=I-J*C,q=P-H*U,st=N-J*U,xt=z-H*K,It=F-J*K,mt=xt*st-It*q,Ot=ft*It-Ct*xt,Me=q*Ct-st*ft;if(a){if(mt<0||Ot<0||Me<0)return null}else if((mt<0||Ot<0||Me<0)&&(mt>0||Ot>0||Me>0))return null;let Lt=mt+Ot+Me;if(Lt===0)return null;let $t=tt*(mt*C+Ot*U+Me*K);return(Lt>0?$t<0:$t>0)?null:this.at($t/Lt,s)}applyMatrix4(t){return this.origin.applyMatrix4(t),this.direction.transformDirection(t),this}equals(t){return t.origin.equals(this.origin)&&t.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},$a=class extends si{constructor(t){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new Ht(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ti,this.combine=gc,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.fog=t.fog,this}},Vu=new se,da=new Jn,go=new We,Hu=new k,bo=new k,xo=new k,yo=new k,gh=new k,_o=new k,Gu=new k,vo=new k,an=class extends Oe{constructor(t=new Le,e=new $a){super(),this.isMesh=!0,this.type="Mesh",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}getVertexPosition(t,e){let n=this.geometry,a=n.attributes.position,s=n.morphAttributes.position,r=n.morphTargetsRelative;e.fromBufferAttribute(a,t);let o=this.morphTargetInfluences;if(s&&o){_o.set(0,0,0);for(let c=0,l=s.length;c<l;c++){let h=o[c],u=s[c];h!==0&&(gh.fromBufferAttribute(u,t),r?_o.addScaledVector(gh,h):_o.addScaledVector(gh.sub(e),h))}e.add(_o)}return e}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.material,s=this.matrixWorld;a!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),go.copy(n.boundingSphere),go.applyMatrix4(s),da.copy(t.ray).recast(t.near),!(go.containsPoint(da.origin)===!1&&(da.intersectSphere(go,Hu)===null||da.origin.distanceToSquared(Hu)>(t.far-t.near)**2))&&(Vu.copy(s).invert(),da.copy(t.ray).applyMatrix4(Vu),!(n.boundingBox!==null&&da.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(t,e,da)))}_computeIntersections(t,e,n){let a,s=this.geometry,r=this.material,o=s.index,c=s.attributes.position,l=s.attributes.uv,h=s.attributes.uv1,u=s.attributes.normal,d=s.groups,f=s.drawRange;if(o!==null)if(Array.isArray(r))for(let b=0,_=d.length;b<_;b++){let m=d[b],x=r[m.materialIndex],v=Math.max(m.start,f.start),w=Math.min(o.count,Math.min(m.start+m.count,f.start+f.count));for(let p=v,y=w;p<y;p+=3){let S=o.getX(p),g=o.getX(p+1),M=o.getX(p+2);a=Mo(this,x,t,n,l,h,u,S,g,M),a&&(a.faceIndex=Math.floor(p/3),a.face.materialIndex=m.materialIndex,e.push(a))}}else{let b=Math.max(0,f.start),_=Math.min(o.count,f.start+f.count);for(let m=b,x=_;m<x;m+=3){let v=o.getX(m),w=o.getX(m+1),p=o.getX(m+2);a=Mo(this,r,t,n,l,h,u,v,w,p),a&&(a.faceIndex=Math.floor(m/3),e.push(a))}}else if(c!==void 0)if(Array.isArray(r))for(let b=0,_=d.length;b<_;b++){let m=d[b],x=r[m.materialIndex],v=Math.max(m.start,f.start),w=Math.min(c.count,Math.min(m.start+m.count,f.start+f.count));for(let p=v,y=w;p<y;p+=3){let S=p,g=p+1,M=p+2;a=Mo(this,x,t,n,l,h,u,S,g,M),a&&(a.faceIndex=Math.floor(p/3),a.face.materialIndex=m.materialIndex,e.push(a))}}else{let b=Math.max(0,f.start),_=Math.min(c.count,f.start+f.count);for(let m=b,x=_;m<x;m+=3){let v=m,w=m+1,p=m+2;a=Mo(this,r,t,n,l,h,u,v,w,p),a&&(a.faceIndex=Math.floor(m/3),e.push(a))}}}};Ai=class extends Sn{constructor(t=null,e=1,n=1,a,s,r,o,c,l=Pe,h=Pe,u,d){super(null,r,o,c,l,h,a,s,u,d),this.isDataTexture=!0,this.image={data:t,width:e,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}},ua=new We,Eb=new Ut(.5,.5),So=new k,Ii=class{constructor(t=new fn,e=new fn,n=new fn,a=new fn,s=new fn,r=new fn){this.planes=[t,e,n,a,s,r]}set(t,e,n,a,s,r){let o=this.planes;return o[0].copy(t),o[1].copy(e),o[2].copy(n),o[3].copy(a),o[4].copy(s),o[5].copy(r),this}copy(t){let e=this.planes;for(let n=0;n<6;n++)e[n].copy(t.planes[n]);return this}setFromProjectionMatrix(t,e=On,n=!1){let a=this.planes,s=t.elements,r=s[0],o=s[1],c=s[2],l=s[3],h=s[4],u=s[5],d=s[6],f=s[7],b=s[8],_=s[9],m=s[10],x=s[11],v=s[12],w=s[13],p=s[14],y=s[15];if(a[0].setComponents(l-r,f-h,x-b,y-v).normalize(),a[1].setComponents(l+r,f+h,x+b,y+v).normalize(),a[2].setComponents(l+o,f+u,x+_,y+w).normalize(),a[3].setComponents(l-o,f-u,x-_,y-w).normalize(),n)a[4].setComponents(c,d,m,p).normalize(),a[5].setComponents(l-c,f-d,x-m,y-p).normalize();else if(a[4].setComponents(l-c,f-d,x-m,y-p).normalize(),e===On)a[5].setComponents(l+c,f+d,x+m,y+p).normalize();else if(e===qa)a[5].setComponents(c,d,m,p).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+e);return this}intersectsObject(t){if(t.boundingSphere!==void 0)t.boundingSphere===null&&t.computeBoundingSphere(),ua.copy(t.boundingSphere).applyMatrix4(t.matrixWorld);else{let e=t.geometry;e.boundingSphere===null&&e.computeBoundingSphere(),ua.copy(e.boundingSphere).applyMatrix4(t.matrixWorld)}return this.intersectsSphere(ua)}intersectsSprite(t){ua.center.set(0,0,0);let e=Eb.distanceTo(t.center);return ua.radius=.7071067811865476+e,ua.applyMatrix4(t.matrixWorld),this.intersectsSphere(ua)}intersectsSphere(t){let e=this.planes,n=t.center,a=-t.radius;for(let s=0;s<6;s++)if(e[s].distanceToPoint(n)<a)return!1;return!0}intersectsBox(t){let e=this.planes;for(let n=0;n<6;n++){let a=e[n];if(So.x=a.normal.x>0?t.max.x:t.min.x,So.y=a.normal.y>0?t.max.y:t.min.y,So.z=a.normal.z>0?t.max.z:t.min.z,a.distanceToPoint(So)<0)return!1}return!0}containsPoint(t){let e=this.planes;for(let n=0;n<6;n++)if(e[n].distanceToPoint(t)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},Wu=new se,nr=class i{constructor(){this.coordinateSystem=On,this._frustums=[],this._count=0}setFromArrayCamera(t){let e=t.cameras,n=this._frustums;for(let a=0;a<e.length;a++){let s=e[a];Wu.multiplyMatrices(s.projectionMatrix,s.matrixWorldInverse),n[a]===void 0&&(n[a]=new Ii),n[a].setFromProjectionMatrix(Wu,s.coordinateSystem,s.reversedDepth)}return this._count=e.length,this}getFrustum(t){return this._frustums[t]}intersectsObject(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsObject(t))return!0;return!1}intersectsSprite(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSprite(t))return!0;return!1}intersectsSphere(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSphere(t))return!0;return!1}intersectsBox(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsBox(t))return!0;return!1}containsPoint(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].containsPoint(t))return!0;return!1}copy(t){this.coordinateSystem=t.coordinateSystem;let e=this._frustums,n=t._frustums;for(let a=0;a<t._count;a++)e[a]===void 0&&(e[a]=new Ii),e[a].copy(n[a]);return this._count=t._count,this}clone(){return new i().copy(this)}};Th=class{constructor(){this.index=0,this.pool=[],this.list=[]}push(t,e,n,a){let s=this.pool,r=this.list;this.index>=s.length&&s.push({start:-1,count:-1,z:-1,index:-1});let o=s[this.index];r.push(o),this.index++,o.start=t,o.count=e,o.z=n,o.index=a}reset(){this.list.length=0,this.index=0}},Mn=new se,Rb=new Ht(1,1,1),Cb=new Ii,Nb=new nr,wo=new Ue,fa=new We,xh=new k,ju=new k,Xu=new k,Pb=new k,yh=new Th,nn=new an,Ao=[];ir=class extends an{constructor(t,e,n=e*2,a){super(new Le,a),this.isBatchedMesh=!0,this.perObjectFrustumCulled=!0,this.sortObjects=!0,this.boundingBox=null,this.boundingSphere=null,this.customSort=null,this._instanceInfo=[],this._geometryInfo=[],this._availableInstanceIds=[],this._availableGeometryIds=[],this._nextIndexStart=0,this._nextVertexStart=0,this._geometryCount=0,this._visibilityChanged=!0,this._geometryInitialized=!1,this._maxInstanceCount=t,this._maxVertexCount=e,this._maxIndexCount=n,this._multiDrawCounts=new Int32Array(t),this._multiDrawStarts=new Int32Array(t),this._multiDrawCount=0,this._multiDrawBytesPerElement=1,this._mergedDrawCounts=new Int32Array(t),this._mergedDrawStarts=new Int32Array(t),this._mergedDrawInstanceCounts=new Int32Array(t),this._mergedDrawCount=0,this._matricesTexture=null,this._indirectTexture=null,this._colorsTexture=null,this._previousMatricesTexture=null,this._initMatricesTexture(),this._initIndirectTexture()}get maxInstanceCount(){return this._maxInstanceCount}get instanceCount(){return this._instanceInfo.length-this._availableInstanceIds.length}get unusedVertexCount(){return this._maxVertexCount-this._nextVertexStart}get unusedIndexCount(){return this._maxIndexCount-this._nextIndexStart}_initMatricesTexture(){let t=Math.sqrt(this._maxInstanceCount*4);t=Math.ceil(t/4)*4,t=Math.max(t,4);let e=new Float32Array(t*t*4),n=new Ai(e,t,t,xn,bn);this._matricesTexture=n}_initIndirectTexture(){let t=Math.sqrt(this._maxInstanceCount);t=Math.ceil(t);let e=new Uint32Array(t*t),n=new Ai(e,t,t,va,wn);this._indirectTexture=n}_initColorsTexture(){let t=Math.sqrt(this._maxInstanceCount);t=Math.ceil(t);let e=new Float32Array(t*t*4).fill(1),n=new Ai(e,t,t,xn,bn);n.colorSpace=Jt.workingColorSpace,this._colorsTexture=n}_initializeGeometry(t){let e=this.geometry,n=this._maxVertexCount,a=this._maxIndexCount;if(this._geometryInitialized===!1){for(let s in t.attributes){let r=t.getAttribute(s),{array:o,itemSize:c,normalized:l}=r,h=new o.constructor(n*c),u=new mn(h,c,l);e.setAttribute(s,u)}if(t.getIndex()!==null){let s=n>65535?new Uint32Array(a):new Uint16Array(a);e.setIndex(new mn(s,1))}this._geometryInitialized=!0}}_validateGeometry(t){let e=this.geometry;if(!!t.getIndex()!=!!e.getIndex())throw new Error('THREE.BatchedMesh: All geometries must consistently have "index".');for(let n in e.attributes){if(!t.hasAttribute(n))throw new Error(`THREE.BatchedMesh: Added geometry missing "${n}". All geometries must have consistent attributes.`);let a=t.getAttribute(n),s=e.getAttribute(n);if(a.itemSize!==s.itemSize||a.normalized!==s.normalized)throw new Error(`THREE.BatchedMesh: Added geometry attribute "${n}" has an inconsistent itemSize or normalized value.`)}}validateInstanceId(t){let e=this._instanceInfo;if(t<0||t>=e.length||e[t].active===!1)throw new Error(`THREE.BatchedMesh: Invalid instanceId ${t}. Instance is either out of range or has been deleted.`)}validateGeometryId(t){let e=this._geometryInfo;if(t<0||t>=e.length||e[t].active===!1)throw new Error(`THREE.BatchedMesh: Invalid geometryId ${t}. Geometry is either out of range or has been deleted.`)}setCustomSort(t){return this.customSort=t,this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ue);let t=this.boundingBox,e=this._instanceInfo;t.makeEmpty();for(let n=0,a=e.length;n<a;n++){if(e[n].active===!1)continue;let s=e[n].geometryIndex;this.getMatrixAt(n,Mn),this.getBoundingBoxAt(s,wo).applyMatrix4(Mn),t.union(wo)}}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new We);let t=this.boundingSphere,e=this._instanceInfo;t.makeEmpty();for(let n=0,a=e.length;n<a;n++){if(e[n].active===!1)continue;let s=e[n].geometryIndex;this.getMatrixAt(n,Mn),this.getBoundingSphereAt(s,fa).applyMatrix4(Mn),t.union(fa)}}addInstance(t){if(this._instanceInfo.length>=this.maxInstanceCount&&this._availableInstanceIds.length===0)throw new Error("THREE.BatchedMesh: Maximum item count reached.");let n={visible:!0,active:!0,geometryIndex:t},a=null;this._availableInstanceIds.length>0?(this._availableInstanceIds.sort(bh),a=this._availableInstanceIds.shift(),this._instanceInfo[a]=n):(a=this._instanceInfo.length,this._instanceInfo.push(n));let s=this._matricesTexture;Mn.identity().toArray(s.image.data,a*16),s.needsUpdate=!0;let r=this._colorsTexture;return r&&(Rb.toArray(r.image.data,a*4),r.needsUpdate=!0),this._visibilityChanged=!0,a}addGeometry(t,e=-1,n=-1){this._initializeGeometry(t),this._validateGeometry(t);let a={vertexStart:-1,vertexCount:-1,reservedVertexCount:-1,indexStart:-1,indexCount:-1,reservedIndexCount:-1,start:-1,count:-1,boundingBox:null,boundingSphere:null,active:!0},s=this._geometryInfo;a.vertexStart=this._nextVertexStart,a.reservedVertexCount=e===-1?t.getAttribute("position").count:e;let r=t.getIndex();if(r!==null&&(a.indexStart=this._nextIndexStart,a.reservedIndexCount=n===-1?r.count:n),a.indexStart!==-1&&a.indexStart+a.reservedIndexCount>this._maxIndexCount||a.vertexStart+a.reservedVertexCount>this._maxVertexCount)throw new Error("THREE.BatchedMesh: Reserved space request exceeds the maximum buffer size.");let c;return this._availableGeometryIds.length>0?(this._availableGeometryIds.sort(bh),c=this._availableGeometryIds.shift(),s[c]=a):(c=this._geometryCount,this._geometryCount++,s.push(a)),this.setGeometryAt(c,t),this._nextIndexStart=a.indexStart+a.reservedIndexCount,this._nextVertexStart=a.vertexStart+a.reservedVertexCount,c}setGeometryAt(t,e){if(t>=this._geometryCount)throw new Error("THREE.BatchedMesh: Maximum geometry count reached.");this._validateGeometry(e);let n=this.geometry,a=n.getIndex()!==null,s=n.getIndex(),r=e.getIndex(),o=this._geometryInfo[t];if(a&&r.count>o.reservedIndexCount||e.attributes.position.count>o.reservedVertexCount)throw new Error("THREE.BatchedMesh: Reserved space not large enough for provided geometry.");let c=o.vertexStart,l=o.reservedVertexCount;o.vertexCount=e.getAttribute("position").count;for(let h in n.attributes){let u=e.getAttribute(h),d=n.getAttribute(h);Lb(u,d,c);let f=u.itemSize;for(let b=u.count,_=l;b<_;b++){let m=c+b;for(let x=0;x<f;x++)d.setComponent(m,x,0)}d.needsUpdate=!0,d.addUpdateRange(c*f,l*f)}if(a){let h=o.indexStart,u=o.reservedIndexCount;o.indexCount=e.getIndex().count;for(let d=0;d<r.count;d++)s.setX(h+d,c+r.getX(d));for(let d=r.count,f=u;d<f;d++)s.setX(h+d,c);s.needsUpdate=!0,s.addUpdateRange(h,o.reservedIndexCount)}return o.start=a?o.indexStart:o.vertexStart,o.count=a?o.indexCount:o.vertexCount,o.boundingBox=null,e.boundingBox!==null&&(o.boundingBox=e.boundingBox.clone()),o.boundingSphere=null,e.boundingSphere!==null&&(o.boundingSphere=e.boundingSphere.clone()),this._visibilityChanged=!0,t}deleteGeometry(t){let e=this._geometryInfo;if(t>=e.length||e[t].active===!1)return this;let n=this._instanceInfo;for(let a=0,s=n.length;a<s;a++)n[a].active&&n[a].geometryIndex===t&&this.deleteInstance(a);return e[t].active=!1,this._availableGeometryIds.push(t),this._visibilityChanged=!0,this}deleteInstance(t){return this.validateInstanceId(t),this._instanceInfo[t].active=!1,this._availableInstanceIds.push(t),this._visibilityChanged=!0,this}optimize(){let t=0,e=0,n=this._geometryInfo,a=n.map((r,o)=>o).sort((r,o)=>n[r].vertexStart-n[o].vertexStart),s=this.geometry;for(let r=0,o=n.length;r<o;r++){let c=a[r],l=n[c];if(l.active!==!1){if(s.index!==null){if(l.indexStart!==e){let{indexStart:h,vertexStart:u,reservedIndexCount:d}=l,f=s.index,b=f.array,_=t-u;for(let m=h;m<h+d;m++)b[m]=b[m]+_;f.array.copyWithin(e,h,h+d),f.addUpdateRange(e,d),f.needsUpdate=!0,l.indexStart=e}e+=l.reservedIndexCount}if(l.vertexStart!==t){let{vertexStart:h,reservedVertexCount:u}=l,d=s.attributes;for(let f in d){let b=d[f],{array:_,itemSize:m}=b;_.copyWithin(t*m,h*m,(h+u)*m),b.addUpdateRange(t*m,u*m),b.needsUpdate=!0}l.vertexStart=t}t+=l.reservedVertexCount,l.start=s.index?l.indexStart:l.vertexStart}}return this._nextIndexStart=e,this._nextVertexStart=t,this._visibilityChanged=!0,this}getBoundingBoxAt(t,e){if(t>=this._geometryCount)return null;let n=this.geometry,a=this._geometryInfo[t];if(a.boundingBox===null){let s=new Ue,r=n.index,o=n.attributes.position;for(let c=a.start,l=a.start+a.count;c<l;c++){let h=c;r&&(h=r.getX(h)),s.expandByPoint(xh.fromBufferAttribute(o,h))}a.boundingBox=s}return e.copy(a.boundingBox),e}getBoundingSphereAt(t,e){if(t>=this._geometryCount)return null;let n=this.geometry,a=this._geometryInfo[t];if(a.boundingSphere===null){let s=new We;this.getBoundingBoxAt(t,wo),wo.getCenter(s.center);let r=n.index,o=n.attributes.position,c=0;for(let l=a.start,h=a.start+a.count;l<h;l++){let u=l;r&&(u=r.getX(u)),xh.fromBufferAttribute(o,u),c=Math.max(c,s.center.distanceToSquared(xh))}s.radius=Math.sqrt(c),a.boundingSphere=s}return e.copy(a.boundingSphere),e}setMatrixAt(t,e){this.validateInstanceId(t);let n=this._matricesTexture,a=this._matricesTexture.image.data;return e.toArray(a,t*16),n.needsUpdate=!0,this}getMatrixAt(t,e){return this.validateInstanceId(t),e.fromArray(this._matricesTexture.image.data,t*16)}setColorAt(t,e){return this.validateInstanceId(t),this._colorsTexture===null&&this._initColorsTexture(),e.toArray(this._colorsTexture.image.data,t*4),this._colorsTexture.needsUpdate=!0,this}getColorAt(t,e){return this.validateInstanceId(t),this._colorsTexture===null?e.isVector4?e.set(1,1,1,1):e.setRGB(1,1,1):e.fromArray(this._colorsTexture.image.data,t*4)}setVisibleAt(t,e){return this.validateInstanceId(t),this._instanceInfo[t].visible===e?this:(this._instanceInfo[t].visible=e,this._visibilityChanged=!0,this)}getVisibleAt(t){return this.validateInstanceId(t),this._instanceInfo[t].visible}setGeometryIdAt(t,e){return this.validateInstanceId(t),this.validateGeometryId(e),this._instanceInfo[t].geometryIndex=e,this._visibilityChanged=!0,this}getGeometryIdAt(t){return this.validateInstanceId(t),this._instanceInfo[t].geometryIndex}getGeometryRangeAt(t,e={}){this.validateGeometryId(t);let n=this._geometryInfo[t];return e.vertexStart=n.vertexStart,e.vertexCount=n.vertexCount,e.reservedVertexCount=n.reservedVertexCount,e.indexStart=n.indexStart,e.indexCount=n.indexCount,e.reservedIndexCount=n.reservedIndexCount,e.start=n.start,e.count=n.count,e}setInstanceCount(t){let e=this._availableInstanceIds,n=this._instanceInfo;for(e.sort(bh);e[e.length-1]===n.length-1;)n.pop(),e.pop();if(t<n.length)throw new Error(`THREE.BatchedMesh: Instance ids outside the range ${t} are being used. Cannot shrink instance count.`);let a=new Int32Array(t),s=new Int32Array(t);ei(this._multiDrawCounts,a),ei(this._multiDrawStarts,s),this._multiDrawCounts=a,this._multiDrawStarts=s;let r=new Int32Array(t),o=new Int32Array(t),c=new Int32Array(t);ei(this._mergedDrawCounts,r),ei(this._mergedDrawStarts,o),ei(this._mergedDrawInstanceCounts,c),this._mergedDrawCounts=r,this._mergedDrawStarts=o,this._mergedDrawInstanceCounts=c,this._maxInstanceCount=t;let l=this._indirectTexture,h=this._matricesTexture,u=this._colorsTexture;l.dispose(),this._initIndirectTexture(),ei(l.image.data,this._indirectTexture.image.data),h.dispose(),this._initMatricesTexture(),ei(h.image.data,this._matricesTexture.image.data),u&&(u.dispose(),this._initColorsTexture(),ei(u.image.data,this._colorsTexture.image.data)),this._previousMatricesTexture!==null&&(this._previousMatricesTexture.dispose(),this._previousMatricesTexture=null)}setGeometrySize(t,e){let n=[...this._geometryInfo].filter(o=>o.active);if(Math.max(...n.map(o=>o.vertexStart+o.reservedVertexCount))>t)throw new Error(`THREE.BatchedMesh: Geometry vertex values are being used outside the range ${t}. Cannot shrink further.`);if(this.geometry.index&&Math.max(...n.map(c=>c.indexStart+c.reservedIndexCount))>e)throw new Error(`THREE.BatchedMesh: Geometry index values are being used outside the range ${e}. Cannot shrink further.`);let s=this.geometry;s.dispose(),this._maxVertexCount=t,this._maxIndexCount=e,this._geometryInitialized&&(this._geometryInitialized=!1,this.geometry=new Le,this._initializeGeometry(s));let r=this.geometry;s.index&&ei(s.index.array,r.index.array);for(let o in s.attributes)ei(s.attributes[o].array,r.attributes[o].array);this._visibilityChanged=!0}raycast(t,e){let n=this._instanceInfo,a=this._geometryInfo,s=this.matrixWorld,r=this.geometry;nn.material=this.material,nn.geometry.index=r.index,nn.geometry.attributes=r.attributes,nn.geometry.boundingBox===null&&(nn.geometry.boundingBox=new Ue),nn.geometry.boundingSphere===null&&(nn.geometry.boundingSphere=new We);for(let o=0,c=n.length;o<c;o++){if(!n[o].visible||!n[o].active)continue;let l=n[o].geometryIndex,h=a[l];nn.geometry.setDrawRange(h.start,h.count),this.getMatrixAt(o,nn.matrixWorld).premultiply(s),this.getBoundingBoxAt(l,nn.geometry.boundingBox),this.getBoundingSphereAt(l,nn.geometry.boundingSphere),nn.raycast(t,Ao);for(let u=0,d=Ao.length;u<d;u++){let f=Ao[u];f.object=this,f.batchId=o,e.push(f)}Ao.length=0}nn.material=null,nn.geometry.index=null,nn.geometry.attributes={},nn.geometry.setDrawRange(0,1/0)}copy(t){return super.copy(t),this.geometry=t.geometry.clone(),this.perObjectFrustumCulled=t.perObjectFrustumCulled,this.sortObjects=t.sortObjects,this.boundingBox=t.boundingBox!==null?t.boundingBox.clone():null,this.boundingSphere=t.boundingSphere!==null?t.boundingSphere.clone():null,this._geometryInfo=t._geometryInfo.map(e=>({...e,boundingBox:e.boundingBox!==null?e.boundingBox.clone():null,boundingSphere:e.boundingSphere!==null?e.boundingSphere.clone():null})),this._instanceInfo=t._instanceInfo.map(e=>({...e})),this._availableInstanceIds=t._availableInstanceIds.slice(),this._availableGeometryIds=t._availableGeometryIds.slice(),this._nextIndexStart=t._nextIndexStart,this._nextVertexStart=t._nextVertexStart,this._geometryCount=t._geometryCount,this._maxInstanceCount=t._maxInstanceCount,this._maxVertexCount=t._maxVertexCount,this._maxIndexCount=t._maxIndexCount,this._geometryInitialized=t._geometryInitialized,this._multiDrawCounts=t._multiDrawCounts.slice(),this._multiDrawStarts=t._multiDrawStarts.slice(),this._multiDrawBytesPerElement=t._multiDrawBytesPerElement,this._mergedDrawCounts=t._mergedDrawCounts.slice(),this._mergedDrawStarts=t._mergedDrawStarts.slice(),this._mergedDrawInstanceCounts=t._mergedDrawInstanceCounts.slice(),this._indirectTexture=t._indirectTexture.clone(),this._indirectTexture.image.data=this._indirectTexture.image.data.slice(),this._matricesTexture=t._matricesTexture.clone(),this._matricesTexture.image.data=this._matricesTexture.image.data.slice(),t._colorsTexture!==null?(this._colorsTexture=t._colorsTexture.clone(),this._colorsTexture.image.data=this._colorsTexture.image.data.slice()):this._colorsTexture=null,this}dispose(){super.dispose(),this.geometry.dispose(),this._matricesTexture.dispose(),this._matricesTexture=null,this._indirectTexture.dispose(),this._indirectTexture=null,this._colorsTexture!==null&&(this._colorsTexture.dispose(),this._colorsTexture=null),this._previousMatricesTexture!==null&&(this._previousMatricesTexture.dispose(),this._previousMatricesTexture=null)}_updateDrawParameters(t,e,n,a="multiDraw"){if(!this._visibilityChanged&&!this.perObjectFrustumCulled&&!this.sortObjects)return;let s=e.getIndex(),r=s===null?1:s.array.BYTES_PER_ELEMENT,o=1;n.wireframe&&(o=2,r=e.attributes.position.count>65535?4:2);let c=this._instanceInfo,l=this._multiDrawStarts,h=this._multiDrawCounts,u=this._mergedDrawStarts,d=this._mergedDrawCounts,f=this._mergedDrawInstanceCounts,b=this._geometryInfo,_=this.perObjectFrustumCulled,m=this._indirectTexture,x=m.image.data,v=t.isArrayCamera?Nb:Cb;_&&(t.isArrayCamera?v.setFromArrayCamera(t):(Mn.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse).multiply(this.matrixWorld),v.setFromProjectionMatrix(Mn,t.coordinateSystem,t.reversedDepth)));let w=0,p=0;if(this.sortObjects){Mn.copy(this.matrixWorld).invert(),ju.setFromMatrixPosition(t.matrixWorld).applyMatrix4(Mn),Xu.set(0,0,-1).transformDirection(t.matrixWorld).transformDirection(Mn);for(let g=0,M=c.length;g<M;g++)if(c[g].visible&&c[g].active){let E=c[g].geometryIndex;this.getMatrixAt(g,Mn),this.getBoundingSphereAt(E,fa).applyMatrix4(Mn);let A=!1;if(_&&(A=!v.intersectsSphere(fa)),!A){let I=b[E],C=Pb.subVectors(fa.center,ju).dot(Xu);yh.push(I.start,I.count,C,g)}}let y=yh.list,S=this.customSort;S===null?y.sort(n.transparent?Ib:Tb):S.call(this,y,t);for(let g=0,M=y.length;g<M;g++){let E=y[g],A=E.start*r*o,I=E.count*o;a==="merged"?p>0&&u[p-1]===A&&d[p-1]===I?f[p-1]++:(u[p]=A,d[p]=I,f[p]=1,p++):(l[w]=A,h[w]=I),x[w]=E.index,w++}yh.reset()}else for(let y=0,S=c.length;y<S;y++)if(c[y].visible&&c[y].active){let g=c[y].geometryIndex,M=!1;if(_&&(this.getMatrixAt(y,Mn),this.getBoundingSphereAt(g,fa).applyMatrix4(Mn),M=!v.intersectsSphere(fa)),!M){let E=b[g],A=E.start*r*o,I=E.count*o;a==="merged"?p>0&&u[p-1]===A&&d[p-1]===I?f[p-1]++:(u[p]=A,d[p]=I,f[p]=1,p++):(l[w]=A,h[w]=I),x[w]=y,w++}}m.needsUpdate=!0,this._multiDrawCount=w,this._mergedDrawCount=p,this._multiDrawBytesPerElement=r,this._visibilityChanged=!1}onBeforeRender(t,e,n,a,s){t.isWebGPURenderer===!0?(this._visibilityChanged||this.perObjectFrustumCulled||this.sortObjects)&&(this._indirectTexture.needsUpdate=!0):this._updateDrawParameters(n,a,s)}onBeforeShadow(t,e,n,a,s,r){t.isWebGPURenderer!==!0&&this._updateDrawParameters(a,s,r)}},pa=class extends si{constructor(t){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new Ht(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.linewidth=t.linewidth,this.linecap=t.linecap,this.linejoin=t.linejoin,this.fog=t.fog,this}},Ko=new k,Zo=new k,qu=new se,Gs=new Jn,Eo=new We,_h=new k,Yu=new k,ma=class extends Oe{constructor(t=new Le,e=new pa){super(),this.isLine=!0,this.type="Line",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}computeLineDistances(){let t=this.geometry;if(t.index===null){let e=t.attributes.position,n=[0];for(let a=1,s=e.count;a<s;a++)Ko.fromBufferAttribute(e,a-1),Zo.fromBufferAttribute(e,a),n[a]=n[a-1],n[a]+=Ko.distanceTo(Zo);t.setAttribute("lineDistance",new me(n,1))}else Dt("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.matrixWorld,s=t.params.Line.threshold,r=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),Eo.copy(n.boundingSphere),Eo.applyMatrix4(a),Eo.radius+=s,t.ray.intersectsSphere(Eo)===!1)return;qu.copy(a).invert(),Gs.copy(t.ray).applyMatrix4(qu);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=this.isLineSegments?2:1,h=n.index,d=n.attributes.position;if(h!==null){let f=Math.max(0,r.start),b=Math.min(h.count,r.start+r.count);for(let _=f,m=b-1;_<m;_+=l){let x=h.getX(_),v=h.getX(_+1),w=To(this,t,Gs,c,x,v,_);w&&e.push(w)}if(this.isLineLoop){let _=h.getX(b-1),m=h.getX(f),x=To(this,t,Gs,c,_,m,b-1);x&&e.push(x)}}else{let f=Math.max(0,r.start),b=Math.min(d.count,r.start+r.count);for(let _=f,m=b-1;_<m;_+=l){let x=To(this,t,Gs,c,_,_+1,_);x&&e.push(x)}if(this.isLineLoop){let _=To(this,t,Gs,c,b-1,f,b-1);_&&e.push(_)}}}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};Ju=new k,Ku=new k,ts=class extends ma{constructor(t,e){super(t,e),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let t=this.geometry;if(t.index===null){let e=t.attributes.position,n=[];for(let a=0,s=e.count;a<s;a+=2)Ju.fromBufferAttribute(e,a),Ku.fromBufferAttribute(e,a+1),n[a]=a===0?0:n[a-1],n[a+1]=n[a]+Ju.distanceTo(Ku);t.setAttribute("lineDistance",new me(n,1))}else Dt("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}},ar=class extends ma{constructor(t,e){super(t,e),this.isLineLoop=!0,this.type="LineLoop"}},Qo=class extends si{constructor(t){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new Ht(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.alphaMap=t.alphaMap,this.size=t.size,this.sizeAttenuation=t.sizeAttenuation,this.fog=t.fog,this}},Zu=new se,Ih=new Jn,Io=new We,Ro=new k,sr=class extends Oe{constructor(t=new Le,e=new Qo){super(),this.isPoints=!0,this.type="Points",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.matrixWorld,s=t.params.Points.threshold,r=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),Io.copy(n.boundingSphere),Io.applyMatrix4(a),Io.radius+=s,t.ray.intersectsSphere(Io)===!1)return;Zu.copy(a).invert(),Ih.copy(t.ray).applyMatrix4(Zu);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=n.index,u=n.attributes.position;if(l!==null){let d=Math.max(0,r.start),f=Math.min(l.count,r.start+r.count);for(let b=d,_=f;b<_;b++){let m=l.getX(b);Ro.fromBufferAttribute(u,m),Qu(Ro,m,c,a,t,e,this)}}else{let d=Math.max(0,r.start),f=Math.min(u.count,r.start+r.count);for(let b=d,_=f;b<_;b++)Ro.fromBufferAttribute(u,b),Qu(Ro,b,c,a,t,e,this)}}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};rr=class extends Sn{constructor(t=[],e=ya,n,a,s,r,o,c,l,h){super(t,e,n,a,s,r,o,c,l,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(t){this.image=t}},Ri=class extends Sn{constructor(t,e,n=wn,a,s,r,o=Pe,c=Pe,l,h=Ei,u=1){if(h!==Ei&&h!==Ni)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let d={width:t,height:e,depth:u};super(d,a,s,r,o,c,h,n,l),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(t){return super.copy(t),this.source=new Ka(Object.assign({},t.image)),this.compareFunction=t.compareFunction,this}toJSON(t){let e=super.toJSON(t);return e.compareFunction=this.compareFunction,e}},or=class extends Ri{constructor(t,e=wn,n=ya,a,s,r=Pe,o=Pe,c,l=Ei){let h={width:t,height:t,depth:1},u=[h,h,h,h,h,h];super(t,t,e,n,a,s,r,o,c,l),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(t){this.image=t}},cr=class extends Sn{constructor(t=null){super(),this.sourceTexture=t,this.isExternalTexture=!0}copy(t){return super.copy(t),this.sourceTexture=t.sourceTexture,this}},es=class i extends Le{constructor(t=1,e=1,n=1,a=1,s=1,r=1){super(),this.type="BoxGeometry",this.parameters={width:t,height:e,depth:n,widthSegments:a,heightSegments:s,depthSegments:r};let o=this;a=Math.floor(a),s=Math.floor(s),r=Math.floor(r);let c=[],l=[],h=[],u=[],d=0,f=0;b("z","y","x",-1,-1,n,e,t,r,s,0),b("z","y","x",1,-1,n,e,-t,r,s,1),b("x","z","y",1,1,t,n,e,a,r,2),b("x","z","y",1,-1,t,n,-e,a,r,3),b("x","y","z",1,-1,t,e,n,a,s,4),b("x","y","z",-1,-1,t,e,-n,a,s,5),this.setIndex(c),this.setAttribute("position",new me(l,3)),this.setAttribute("normal",new me(h,3)),this.setAttribute("uv",new me(u,2));function b(_,m,x,v,w,p,y,S,g,M,E){let A=p/g,I=y/M,C=p/2,P=y/2,N=S/2,U=g+1,z=M+1,F=0,K=0,H=new k;for(let J=0;J<z;J++){let tt=J*I-P;for(let ft=0;ft<U;ft++){let Ct=ft*A-C;H[_]=Ct*v,H[m]=tt*w,H[x]=N,l.push(H.x,H.y,H.z),H[_]=0,H[m]=0,H[x]=S>0?1:-1,h.push(H.x,H.y,H.z),u.push(ft/g),u.push(1-J/M),F+=1}}for(let J=0;J<M;J++)for(let tt=0;tt<g;tt++){let ft=d+tt+U*J,Ct=d+tt+U*(J+1),q=d+(tt+1)+U*(J+1),st=d+(tt+1)+U*J;c.push(ft,Ct,st),c.push(Ct,q,st),K+=6}o.addGroup(f,K,E),f+=K,d+=F}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.width,t.height,t.depth,t.widthSegments,t.heightSegments,t.depthSegments)}},ns=class i extends Le{constructor(t=1,e=1,n=1,a=32,s=1,r=!1,o=0,c=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:t,radiusBottom:e,height:n,radialSegments:a,heightSegments:s,openEnded:r,thetaStart:o,thetaLength:c};let l=this;a=Math.floor(a),s=Math.floor(s);let h=[],u=[],d=[],f=[],b=0,_=[],m=n/2,x=0;v(),r===!1&&(t>0&&w(!0),e>0&&w(!1)),this.setIndex(h),this.setAttribute("position",new me(u,3)),this.setAttribute("normal",new me(d,3)),this.setAttribute("uv",new me(f,2));function v(){let p=new k,y=new k,S=0,g=(e-t)/n;for(let M=0;M<=s;M++){let E=[],A=M/s,I=A*(e-t)+t;for(let C=0;C<=a;C++){let P=C/a,N=P*c+o,U=Math.sin(N),z=Math.cos(N);y.x=I*U,y.y=-A*n+m,y.z=I*z,u.push(y.x,y.y,y.z),p.set(U,g,z).normalize(),d.push(p.x,p.y,p.z),f.push(P,1-A),E.push(b++)}_.push(E)}for(let M=0;M<a;M++)for(let E=0;E<s;E++){let A=_[E][M],I=_[E+1][M],C=_[E+1][M+1],P=_[E][M+1];(t>0||E!==0)&&(h.push(A,I,P),S+=3),(e>0||E!==s-1)&&(h.push(I,C,P),S+=3)}l.addGroup(x,S,0),x+=S}function w(p){let y=b,S=new Ut,g=new k,M=0,E=p===!0?t:e,A=p===!0?1:-1;for(let C=1;C<=a;C++)u.push(0,m*A,0),d.push(0,A,0),f.push(.5,.5),b++;let I=b;for(let C=0;C<=a;C++){let N=C/a*c+o,U=Math.cos(N),z=Math.sin(N);g.x=E*z,g.y=m*A,g.z=E*U,u.push(g.x,g.y,g.z),d.push(0,A,0),S.x=U*.5+.5,S.y=z*.5*A+.5,f.push(S.x,S.y),b++}for(let C=0;C<a;C++){let P=y+C,N=I+C;p===!0?h.push(N,N+1,P):h.push(N+1,N,P),M+=3}l.addGroup(x,M,p===!0?1:2),x+=M}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radiusTop,t.radiusBottom,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}},lr=class i extends ns{constructor(t=1,e=1,n=32,a=1,s=!1,r=0,o=Math.PI*2){super(0,t,e,n,a,s,r,o),this.type="ConeGeometry",this.parameters={radius:t,height:e,radialSegments:n,heightSegments:a,openEnded:s,thetaStart:r,thetaLength:o}}static fromJSON(t){return new i(t.radius,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}},hr=class i extends Le{constructor(t=1,e=1,n=1,a=1){super(),this.type="PlaneGeometry",this.parameters={width:t,height:e,widthSegments:n,heightSegments:a};let s=t/2,r=e/2,o=Math.floor(n),c=Math.floor(a),l=o+1,h=c+1,u=t/o,d=e/c,f=[],b=[],_=[],m=[];for(let x=0;x<h;x++){let v=x*d-r;for(let w=0;w<l;w++){let p=w*u-s;b.push(p,-v,0),_.push(0,0,1),m.push(w/o),m.push(1-x/c)}}for(let x=0;x<c;x++)for(let v=0;v<o;v++){let w=v+l*x,p=v+l*(x+1),y=v+1+l*(x+1),S=v+1+l*x;f.push(w,p,S),f.push(p,y,S)}this.setIndex(f),this.setAttribute("position",new me(b,3)),this.setAttribute("normal",new me(_,3)),this.setAttribute("uv",new me(m,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.width,t.height,t.widthSegments,t.heightSegments)}},dr=class i extends Le{constructor(t=1,e=32,n=16,a=0,s=Math.PI*2,r=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:t,widthSegments:e,heightSegments:n,phiStart:a,phiLength:s,thetaStart:r,thetaLength:o},e=Math.max(3,Math.floor(e)),n=Math.max(2,Math.floor(n));let c=Math.min(r+o,Math.PI),l=0,h=[],u=new k,d=new k,f=[],b=[],_=[],m=[];for(let x=0;x<=n;x++){let v=[],w=x/n,p=r+w*o,y=t*Math.cos(p),S=Math.sqrt(t*t-y*y),g=0;x===0&&r===0?g=.5/e:x===n&&c===Math.PI&&(g=-.5/e);for(let M=0;M<=e;M++){let E=M/e,A=a+E*s;u.x=-S*Math.cos(A),u.y=y,u.z=S*Math.sin(A),b.push(u.x,u.y,u.z),d.copy(u).normalize(),_.push(d.x,d.y,d.z),m.push(E+g,1-w),v.push(l++)}h.push(v)}for(let x=0;x<n;x++)for(let v=0;v<e;v++){let w=h[x][v+1],p=h[x][v],y=h[x+1][v],S=h[x+1][v+1];(x!==0||r>0)&&f.push(w,p,S),(x!==n-1||c<Math.PI)&&f.push(p,y,S)}this.setIndex(f),this.setAttribute("position",new me(b,3)),this.setAttribute("normal",new me(_,3)),this.setAttribute("uv",new me(m,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radius,t.widthSegments,t.heightSegments,t.phiStart,t.phiLength,t.thetaStart,t.thetaLength)}},ur=class i extends Le{constructor(t=1,e=.4,n=12,a=48,s=Math.PI*2,r=0,o=Math.PI*2){super(),this.type="TorusGeometry",this.parameters={radius:t,tube:e,radialSegments:n,tubularSegments:a,arc:s,thetaStart:r,thetaLength:o},n=Math.floor(n),a=Math.floor(a);let c=[],l=[],h=[],u=[],d=new k,f=new k,b=new k;for(let _=0;_<=n;_++){let m=r+_/n*o;for(let x=0;x<=a;x++){let v=x/a*s;f.x=(t+e*Math.cos(m))*Math.cos(v),f.y=(t+e*Math.cos(m))*Math.sin(v),f.z=e*Math.sin(m),l.push(f.x,f.y,f.z),d.x=t*Math.cos(v),d.y=t*Math.sin(v),b.subVectors(f,d).normalize(),h.push(b.x,b.y,b.z),u.push(x/a),u.push(_/n)}}for(let _=1;_<=n;_++)for(let m=1;m<=a;m++){let x=(a+1)*_+m-1,v=(a+1)*(_-1)+m-1,w=(a+1)*(_-1)+m,p=(a+1)*_+m;c.push(x,v,p),c.push(v,w,p)}this.setIndex(c),this.setAttribute("position",new me(l,3)),this.setAttribute("normal",new me(h,3)),this.setAttribute("uv",new me(u,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radius,t.tube,t.radialSegments,t.tubularSegments,t.arc,t.thetaStart,t.thetaLength)}},fr=class extends Le{constructor(t=null){if(super(),this.type="WireframeGeometry",this.parameters={geometry:t},t!==null){let e=[],n=new Set,a=new k,s=new k;if(t.index!==null){let r=t.attributes.position,o=t.index,c=t.groups;c.length===0&&(c=[{start:0,count:o.count,materialIndex:0}]);for(let l=0,h=c.length;l<h;++l){let u=c[l],d=u.start,f=u.count;for(let b=d,_=d+f;b<_;b+=3)for(let m=0;m<3;m++){let x=o.getX(b+m),v=o.getX(b+(m+1)%3);a.fromBufferAttribute(r,x),s.fromBufferAttribute(r,v),$u(a,s,n)===!0&&(e.push(a.x,a.y,a.z),e.push(s.x,s.y,s.z))}}}else{let r=t.attributes.position;for(let o=0,c=r.count/3;o<c;o++)for(let l=0;l<3;l++){let h=3*o+l,u=3*o+(l+1)%3;a.fromBufferAttribute(r,h),s.fromBufferAttribute(r,u),$u(a,s,n)===!0&&(e.push(a.x,a.y,a.z),e.push(s.x,s.y,s.z))}}this.setAttribute("position",new me(e,3))}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}};Or={clone:Sa,merge:rn},Ub=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,Ob=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,Fn=class extends si{constructor(t){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=Ub,this.fragmentShader=Ob,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,t!==void 0&&this.setValues(t)}copy(t){return super.copy(t),this.fragmentShader=t.fragmentShader,this.vertexShader=t.vertexShader,this.uniforms=Sa(t.uniforms),this.uniformsGroups=Db(t.uniformsGroups),this.defines=Object.assign({},t.defines),this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.fog=t.fog,this.lights=t.lights,this.clipping=t.clipping,this.extensions=Object.assign({},t.extensions),this.glslVersion=t.glslVersion,this.defaultAttributeValues=Object.assign({},t.defaultAttributeValues),this.index0AttributeName=t.index0AttributeName,this.uniformsNeedUpdate=t.uniformsNeedUpdate,this}toJSON(t){let e=super.toJSON(t);e.glslVersion=this.glslVersion,e.uniforms={};for(let a in this.uniforms){let r=this.uniforms[a].value;r&&r.isTexture?e.uniforms[a]={type:"t",value:r.toJSON(t).uuid}:r&&r.isColor?e.uniforms[a]={type:"c",value:r.getHex()}:r&&r.isVector2?e.uniforms[a]={type:"v2",value:r.toArray()}:r&&r.isVector3?e.uniforms[a]={type:"v3",value:r.toArray()}:r&&r.isVector4?e.uniforms[a]={type:"v4",value:r.toArray()}:r&&r.isMatrix3?e.uniforms[a]={type:"m3",value:r.toArray()}:r&&r.isMatrix4?e.uniforms[a]={type:"m4",value:r.toArray()}:e.uniforms[a]={value:r}}Object.keys(this.defines).length>0&&(e.defines=this.defines),e.vertexShader=this.vertexShader,e.fragmentShader=this.fragmentShader,e.lights=this.lights,e.clipping=this.clipping;let n={};for(let a in this.extensions)this.extensions[a]===!0&&(n[a]=!0);return Object.keys(n).length>0&&(e.extensions=n),e}fromJSON(t,e){if(super.fromJSON(t,e),t.uniforms!==void 0)for(let n in t.uniforms){let a=t.uniforms[n];switch(this.uniforms[n]={},a.type){case"t":this.uniforms[n].value=e[a.value]||null;break;case"c":this.uniforms[n].value=new Ht().setHex(a.value);break;case"v2":this.uniforms[n].value=new Ut().fromArray(a.value);break;case"v3":this.uniforms[n].value=new k().fromArray(a.value);break;case"v4":this.uniforms[n].value=new re().fromArray(a.value);break;case"m3":this.uniforms[n].value=new Bt().fromArray(a.value);break;case"m4":this.uniforms[n].value=new se().fromArray(a.value);break;default:this.uniforms[n].value=a.value}}if(t.defines!==void 0&&(this.defines=t.defines),t.vertexShader!==void 0&&(this.vertexShader=t.vertexShader),t.fragmentShader!==void 0&&(this.fragmentShader=t.fragmentShader),t.glslVersion!==void 0&&(this.glslVersion=t.glslVersion),t.extensions!==void 0)for(let n in t.extensions)this.extensions[n]=t.extensions[n];return t.lights!==void 0&&(this.lights=t.lights),t.clipping!==void 0&&(this.clipping=t.clipping),this}},$o=class extends Fn{constructor(t){super(t),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}},pr=class extends si{constructor(t){super(),this.isMeshLambertMaterial=!0,this.type="MeshLambertMaterial",this.color=new Ht(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new Ht(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Qc,this.normalScale=new Ut(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ti,this.combine=gc,this.reflectivity=1,this.envMapIntensity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.emissive.copy(t.emissive),this.emissiveMap=t.emissiveMap,this.emissiveIntensity=t.emissiveIntensity,this.bumpMap=t.bumpMap,this.bumpScale=t.bumpScale,this.normalMap=t.normalMap,this.normalMapType=t.normalMapType,this.normalScale.copy(t.normalScale),this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.envMapIntensity=t.envMapIntensity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.flatShading=t.flatShading,this.fog=t.fog,this}},tc=class extends si{constructor(t){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=Uf,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(t)}copy(t){return super.copy(t),this.depthPacking=t.depthPacking,this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this}},ec=class extends si{constructor(t){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(t)}copy(t){return super.copy(t),this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this}};Gi=class{constructor(t,e,n,a){this.parameterPositions=t,this._cachedIndex=0,this.resultBuffer=a!==void 0?a:new e.constructor(n),this.sampleValues=e,this.valueSize=n,this.settings=null,this.DefaultSettings_={}}evaluate(t){let e=this.parameterPositions,n=this._cachedIndex,a=e[n],s=e[n-1];n:{t:{let r;e:{i:if(!(t<a)){for(let o=n+2;;){if(a===void 0){if(t<s)break i;return n=e.length,this._cachedIndex=n,this.copySampleValue_(n-1)}if(n===o)break;if(s=a,a=e[++n],t<a)break t}r=e.length;break e}if(!(t>=s)){let o=e[1];t<o&&(n=2,s=o);for(let c=n-2;;){if(s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(n===c)break;if(a=s,s=e[--n-1],t>=s)break t}r=n,n=0;break e}break n}for(;n<r;){let o=n+r>>>1;t<e[o]?r=o:n=o+1}if(a=e[n],s=e[n-1],s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(a===void 0)return n=e.length,this._cachedIndex=n,this.copySampleValue_(n-1)}this._cachedIndex=n,this.intervalChanged_(n,s,a)}return this.interpolate_(n,s,t,a)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(t){let e=this.resultBuffer,n=this.sampleValues,a=this.valueSize,s=t*a;for(let r=0;r!==a;++r)e[r]=n[s+r];return e}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},nc=class extends Gi{constructor(t,e,n,a){super(t,e,n,a),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:wh,endingEnd:wh}}intervalChanged_(t,e,n){let a=this.parameterPositions,s=t-2,r=t+1,o=a[s],c=a[r];if(o===void 0)switch(this.getSettings_().endingStart){case Ah:s=t,o=2*e-n;break;case Eh:s=a.length-2,o=e+a[s]-a[s+1];break;default:s=t,o=n}if(c===void 0)switch(this.getSettings_().endingEnd){case Ah:r=t,c=2*n-e;break;case Eh:r=1,c=n+a[1]-a[0];break;default:r=t-1,c=e}let l=(n-e)*.5,h=this.valueSize;this._weightPrev=l/(e-o),this._weightNext=l/(c-n),this._offsetPrev=s*h,this._offsetNext=r*h}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=this._offsetPrev,u=this._offsetNext,d=this._weightPrev,f=this._weightNext,b=(n-e)/(a-e),_=b*b,m=_*b,x=-d*m+2*d*_-d*b,v=(1+d)*m+(-1.5-2*d)*_+(-.5+d)*b+1,w=(-1-f)*m+(1.5+f)*_+.5*b,p=f*m-f*_;for(let y=0;y!==o;++y)s[y]=x*r[h+y]+v*r[l+y]+w*r[c+y]+p*r[u+y];return s}},ic=class extends Gi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=(n-e)/(a-e),u=1-h;for(let d=0;d!==o;++d)s[d]=r[l+d]*u+r[c+d]*h;return s}},ac=class extends Gi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t){return this.copySampleValue_(t-1)}},sc=class extends Gi{interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=this.inTangents,u=this.outTangents;if(!h||!u){let b=(n-e)/(a-e),_=1-b;for(let m=0;m!==o;++m)s[m]=r[l+m]*_+r[c+m]*b;return s}let d=o*2,f=t-1;for(let b=0;b!==o;++b){let _=r[l+b],m=r[c+b],x=f*d+b*2,v=u[x],w=u[x+1],p=t*d+b*2,y=h[p],S=h[p+1],g=Bb(n,e,v,y,a);s[b]=Yf(g,_,w,S,m)}return s}};Nn=class{constructor(t,e,n,a){if(t===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(e===void 0||e.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+t);this.name=t,this.times=za(e,this.TimeBufferType),this.values=za(n,this.ValueBufferType),this.setInterpolation(a||this.DefaultInterpolation)}static toJSON(t){let e=t.constructor,n;if(e.toJSON!==this.toJSON)n=e.toJSON(t);else{n={name:t.name,times:za(t.times,Array),values:za(t.values,Array)};let a=t.getInterpolation();a!==t.DefaultInterpolation&&(n.interpolation=a),Co(t.settings)&&(n.settings={inTangents:za(t.settings.inTangents,Array),outTangents:za(t.settings.outTangents,Array)})}return n.type=t.ValueTypeName,n}InterpolantFactoryMethodDiscrete(t){return new ac(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodLinear(t){return new ic(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodSmooth(t){return new nc(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodBezier(t){let e=new sc(this.times,this.values,this.getValueSize(),t);return this.settings&&(e.inTangents=this.settings.inTangents,e.outTangents=this.settings.outTangents),e}setInterpolation(t){let e;switch(t){case qs:e=this.InterpolantFactoryMethodDiscrete;break;case jo:e=this.InterpolantFactoryMethodLinear;break;case Do:e=this.InterpolantFactoryMethodSmooth;break;case Sh:e=this.InterpolantFactoryMethodBezier;break}if(e===void 0){let n="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(t!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(n);return Dt("KeyframeTrack:",n),this}return this.createInterpolant=e,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return qs;case this.InterpolantFactoryMethodLinear:return jo;case this.InterpolantFactoryMethodSmooth:return Do;case this.InterpolantFactoryMethodBezier:return Sh}}getValueSize(){return this.values.length/this.times.length}shift(t){if(t!==0){let e=this.times;for(let n=0,a=e.length;n!==a;++n)e[n]+=t;Co(this.settings)&&(ef(this.settings.inTangents,t),ef(this.settings.outTangents,t))}return this}scale(t){if(t!==1){let e=this.times;for(let n=0,a=e.length;n!==a;++n)e[n]*=t;Co(this.settings)&&(nf(this.settings.inTangents,t),nf(this.settings.outTangents,t))}return this}trim(t,e){let n=this.times,a=n.length,s=0,r=a-1;for(;s!==a&&n[s]<t;)++s;for(;r!==-1&&n[r]>e;)--r;if(++r,s!==0||r!==a){s>=r&&(r=Math.max(r,1),s=r-1);let o=this.getValueSize();this.times=n.slice(s,r),this.values=this.values.slice(s*o,r*o)}return this}validate(){let t=!0,e=this.getValueSize();e-Math.floor(e)!==0&&(Ft("KeyframeTrack: Invalid value size in track.",this),t=!1);let n=this.times,a=this.values,s=n.length;s===0&&(Ft("KeyframeTrack: Track is empty.",this),t=!1);let r=null;for(let o=0;o!==s;o++){let c=n[o];if(typeof c=="number"&&isNaN(c)){Ft("KeyframeTrack: Time is not a valid number.",this,o,c),t=!1;break}if(r!==null&&r>c){Ft("KeyframeTrack: Out of order keys.",this,o,c,r),t=!1;break}r=c}if(a!==void 0&&qg(a))for(let o=0,c=a.length;o!==c;++o){let l=a[o];if(isNaN(l)){Ft("KeyframeTrack: Value is not a valid number.",this,o,l),t=!1;break}}return t}optimize(){let t=this.times.slice(),e=this.values.slice(),n=this.getValueSize(),a=this.getInterpolation()===Do,s=t.length-1,r=1;for(let o=1;o<s;++o){let c=!1,l=t[o],h=t[o+1];if(l!==h&&(o!==1||l!==t[0]))if(a)c=!0;else{let u=o*n,d=u-n,f=u+n;for(let b=0;b!==n;++b){let _=e[u+b];if(_!==e[d+b]||_!==e[f+b]){c=!0;break}}}if(c){if(o!==r){t[r]=t[o];let u=o*n,d=r*n;for(let f=0;f!==n;++f)e[d+f]=e[u+f]}++r}}if(s>0){t[r]=t[s];for(let o=s*n,c=r*n,l=0;l!==n;++l)e[c+l]=e[o+l];++r}return r!==t.length?(this.times=t.slice(0,r),this.values=e.slice(0,r*n)):(this.times=t,this.values=e),this}clone(){let t=this.times.slice(),e=this.values.slice(),n=this.constructor,a=new n(this.name,t,e);return a.createInterpolant=this.createInterpolant,Co(this.settings)&&(a.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),a}};Nn.prototype.ValueTypeName="";Nn.prototype.TimeBufferType=Float32Array;Nn.prototype.ValueBufferType=Float32Array;Nn.prototype.DefaultInterpolation=jo;Wi=class extends Nn{constructor(t,e,n){super(t,e,n)}};Wi.prototype.ValueTypeName="bool";Wi.prototype.ValueBufferType=Array;Wi.prototype.DefaultInterpolation=qs;Wi.prototype.InterpolantFactoryMethodLinear=void 0;Wi.prototype.InterpolantFactoryMethodSmooth=void 0;rc=class extends Nn{constructor(t,e,n,a){super(t,e,n,a)}};rc.prototype.ValueTypeName="color";oc=class extends Nn{constructor(t,e,n,a){super(t,e,n,a)}};oc.prototype.ValueTypeName="number";cc=class extends Gi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=(n-e)/(a-e),l=t*o;for(let h=l+o;l!==h;l+=4)Rn.slerpFlat(s,0,r,l-o,r,l,c);return s}},mr=class extends Nn{constructor(t,e,n,a){super(t,e,n,a)}InterpolantFactoryMethodLinear(t){return new cc(this.times,this.values,this.getValueSize(),t)}};mr.prototype.ValueTypeName="quaternion";mr.prototype.InterpolantFactoryMethodSmooth=void 0;ji=class extends Nn{constructor(t,e,n){super(t,e,n)}};ji.prototype.ValueTypeName="string";ji.prototype.ValueBufferType=Array;ji.prototype.DefaultInterpolation=qs;ji.prototype.InterpolantFactoryMethodLinear=void 0;ji.prototype.InterpolantFactoryMethodSmooth=void 0;lc=class extends Nn{constructor(t,e,n,a){super(t,e,n,a)}};lc.prototype.ValueTypeName="vector";hc=class{constructor(t,e,n){let a=this,s=!1,r=0,o=0,c,l=[];this.onStart=void 0,this.onLoad=t,this.onProgress=e,this.onError=n,this._abortController=null,this.itemStart=function(h){o++,s===!1&&a.onStart!==void 0&&a.onStart(h,r,o),s=!0},this.itemEnd=function(h){r++,a.onProgress!==void 0&&a.onProgress(h,r,o),r===o&&(s=!1,a.onLoad!==void 0&&a.onLoad())},this.itemError=function(h){a.onError!==void 0&&a.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),c?c(h):h},this.setURLModifier=function(h){return c=h,this},this.addHandler=function(h,u){return l.push(h,u),this},this.removeHandler=function(h){let u=l.indexOf(h);return u!==-1&&l.splice(u,2),this},this.getHandler=function(h){for(let u=0,d=l.length;u<d;u+=2){let f=l[u],b=l[u+1];if(f.global&&(f.lastIndex=0),f.test(h))return b}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},Jf=new hc,dc=class{constructor(t){this.manager=t!==void 0?t:Jf,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(t,e){let n=this;return new Promise(function(a,s){n.load(t,a,e,s)})}parse(){}setCrossOrigin(t){return this.crossOrigin=t,this}setWithCredentials(t){return this.withCredentials=t,this}setPath(t){return this.path=t,this}setResourcePath(t){return this.resourcePath=t,this}setRequestHeader(t){return this.requestHeader=t,this}setPriority(t){return this.priority=t,this}setCache(t){return this.cache=t,this}abort(){return this}};dc.DEFAULT_MATERIAL_NAME="__DEFAULT";gr=class extends Oe{static registerNode(t){this.prototype._lightNode=t}constructor(t,e=1){super(),this.isLight=!0,this.type="Light",this.color=new Ht(t),this.intensity=e}copy(t,e){return super.copy(t,e),this.color.copy(t.color),this.intensity=t.intensity,this}toJSON(t){let e=super.toJSON(t);return e.object.color=this.color.getHex(),e.object.intensity=this.intensity,e}},vh=new se,af=new k,sf=new k,uc=class{constructor(t){this.camera=t,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Ut(512,512),this.mapType=sn,this.map=null,this.mapPass=null,this.matrix=new se,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Ii,this._frameExtents=new Ut(1,1),this._viewportCount=1,this._viewports=[new re(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(t){let e=this.camera;af.setFromMatrixPosition(t.matrixWorld),e.position.copy(af),sf.setFromMatrixPosition(t.target.matrixWorld),e.lookAt(sf),e.updateMatrixWorld(),this._updateMatrix(e,this.matrix,this._frustum)}_updateMatrix(t,e,n,a){vh.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse),n.setFromProjectionMatrix(vh,t.coordinateSystem,t.reversedDepth);let s=this._frameExtents,r=a?a.z/s.x:1,o=a?a.w/s.y:1,c=a?a.x/s.x:0,l=a?a.y/s.y:0;t.coordinateSystem===qa||t.reversedDepth?e.set(.5*r,0,0,.5*r+c,0,.5*o,0,.5*o+l,0,0,1,0,0,0,0,1):e.set(.5*r,0,0,.5*r+c,0,.5*o,0,.5*o+l,0,0,.5,.5,0,0,0,1),e.multiply(vh)}getViewport(t){return this._viewports[t]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(t){return this.camera=t.camera.clone(),this.intensity=t.intensity,this.bias=t.bias,this.radius=t.radius,this.autoUpdate=t.autoUpdate,this.needsUpdate=t.needsUpdate,this.normalBias=t.normalBias,this.blurSamples=t.blurSamples,this.mapSize.copy(t.mapSize),this.mapType=t.mapType,this.biasNode=t.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){let t={};return t.intensity=this.intensity,t.bias=this.bias,t.normalBias=this.normalBias,t.radius=this.radius,t.blurSamples=this.blurSamples,t.mapSize=this.mapSize.toArray(),t.mapType=this.mapType,t.camera=this.camera.toJSON(!1).object,delete t.camera.matrix,t}},No=new k,Po=new Rn,ni=new k,br=class extends Oe{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new se,this.projectionMatrix=new se,this.projectionMatrixInverse=new se,this.coordinateSystem=On,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(t,e){return super.copy(t,e),this.matrixWorldInverse.copy(t.matrixWorldInverse),this.projectionMatrix.copy(t.projectionMatrix),this.projectionMatrixInverse.copy(t.projectionMatrixInverse),this.coordinateSystem=t.coordinateSystem,this}getWorldDirection(t){return super.getWorldDirection(t).negate()}updateMatrixWorld(t){super.updateMatrixWorld(t),this.matrixWorld.decompose(No,Po,ni),ni.x===1&&ni.y===1&&ni.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(No,Po,ni.set(1,1,1)).invert()}updateWorldMatrix(t,e,n=!1){super.updateWorldMatrix(t,e,n),this.matrixWorld.decompose(No,Po,ni),ni.x===1&&ni.y===1&&ni.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(No,Po,ni.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},Hi=new k,rf=new Ut,of=new Ut,pn=class extends br{constructor(t=50,e=1,n=.1,a=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=t,this.zoom=1,this.near=n,this.far=a,this.focus=10,this.aspect=e,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.fov=t.fov,this.zoom=t.zoom,this.near=t.near,this.far=t.far,this.focus=t.focus,this.aspect=t.aspect,this.view=t.view===null?null:Object.assign({},t.view),this.filmGauge=t.filmGauge,this.filmOffset=t.filmOffset,this}setFocalLength(t){let e=.5*this.getFilmHeight()/t;this.fov=Ja*2*Math.atan(e),this.updateProjectionMatrix()}getFocalLength(){let t=Math.tan(js*.5*this.fov);return .5*this.getFilmHeight()/t}getEffectiveFOV(){return Ja*2*Math.atan(Math.tan(js*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(t,e,n){Hi.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),e.set(Hi.x,Hi.y).multiplyScalar(-t/Hi.z),Hi.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(Hi.x,Hi.y).multiplyScalar(-t/Hi.z)}getViewSize(t,e){return this.getViewBounds(t,rf,of),e.subVectors(of,rf)}setViewOffset(t,e,n,a,s,r){this.aspect=t/e,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=a,this.view.width=s,this.view.height=r,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let t=this.near,e=t*Math.tan(js*.5*this.fov)/this.zoom,n=2*e,a=this.aspect*n,s=-.5*a,r=this.view;if(this.view!==null&&this.view.enabled){let c=r.fullWidth,l=r.fullHeight;s+=r.offsetX*a/c,e-=r.offsetY*n/l,a*=r.width/c,n*=r.height/l}let o=this.filmOffset;o!==0&&(s+=t*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(s,s+a,e,e-n,t,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){let e=super.toJSON(t);return e.object.fov=this.fov,e.object.zoom=this.zoom,e.object.near=this.near,e.object.far=this.far,e.object.focus=this.focus,e.object.aspect=this.aspect,this.view!==null&&(e.object.view=Object.assign({},this.view)),e.object.filmGauge=this.filmGauge,e.object.filmOffset=this.filmOffset,e}},xr=class extends br{constructor(t=-1,e=1,n=1,a=-1,s=.1,r=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=t,this.right=e,this.top=n,this.bottom=a,this.near=s,this.far=r,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.left=t.left,this.right=t.right,this.top=t.top,this.bottom=t.bottom,this.near=t.near,this.far=t.far,this.zoom=t.zoom,this.view=t.view===null?null:Object.assign({},t.view),this}setViewOffset(t,e,n,a,s,r){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=a,this.view.width=s,this.view.height=r,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let t=(this.right-this.left)/(2*this.zoom),e=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,a=(this.top+this.bottom)/2,s=n-t,r=n+t,o=a+e,c=a-e;if(this.view!==null&&this.view.enabled){let l=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;s+=l*this.view.offsetX,r=s+l*this.view.width,o-=h*this.view.offsetY,c=o-h*this.view.height}this.projectionMatrix.makeOrthographic(s,r,o,c,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){let e=super.toJSON(t);return e.object.zoom=this.zoom,e.object.left=this.left,e.object.right=this.right,e.object.top=this.top,e.object.bottom=this.bottom,e.object.near=this.near,e.object.far=this.far,this.view!==null&&(e.object.view=Object.assign({},this.view)),e}},Rh=class extends uc{constructor(){super(new xr(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}},yr=class extends gr{constructor(t,e){super(t,e),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Oe.DEFAULT_UP),this.updateMatrix(),this.target=new Oe,this.shadow=new Rh}dispose(){super.dispose(),this.shadow.dispose()}copy(t){return super.copy(t),this.target=t.target.clone(),this.shadow=t.shadow.clone(),this}toJSON(t){let e=super.toJSON(t);return e.object.shadow=this.shadow.toJSON(),e.object.target=this.target.uuid,e}},_r=class extends gr{constructor(t,e){super(t,e),this.isAmbientLight=!0,this.type="AmbientLight"}},vr=class extends Le{constructor(){super(),this.isInstancedBufferGeometry=!0,this.type="InstancedBufferGeometry",this.instanceCount=1/0}copy(t){return super.copy(t),this.instanceCount=t.instanceCount,this}toJSON(){let t=super.toJSON();return t.instanceCount=this.instanceCount,t.isInstancedBufferGeometry=!0,t}},Va=-90,Ha=1,is=class extends Oe{constructor(t,e,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;let a=new pn(Va,Ha,t,e);a.layers=this.layers,this.add(a);let s=new pn(Va,Ha,t,e);s.layers=this.layers,this.add(s);let r=new pn(Va,Ha,t,e);r.layers=this.layers,this.add(r);let o=new pn(Va,Ha,t,e);o.layers=this.layers,this.add(o);let c=new pn(Va,Ha,t,e);c.layers=this.layers,this.add(c);let l=new pn(Va,Ha,t,e);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){let t=this.coordinateSystem,e=this.children.concat(),[n,a,s,r,o,c]=e;for(let l of e)this.remove(l);if(t===On)n.up.set(0,1,0),n.lookAt(1,0,0),a.up.set(0,1,0),a.lookAt(-1,0,0),s.up.set(0,0,-1),s.lookAt(0,1,0),r.up.set(0,0,1),r.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(t===qa)n.up.set(0,-1,0),n.lookAt(-1,0,0),a.up.set(0,-1,0),a.lookAt(1,0,0),s.up.set(0,0,1),s.lookAt(0,1,0),r.up.set(0,0,-1),r.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+t);for(let l of e)this.add(l),l.updateMatrixWorld()}update(t,e){this.parent===null&&this.updateMatrixWorld();let{renderTarget:n,activeMipmapLevel:a}=this;this.coordinateSystem!==t.coordinateSystem&&(this.coordinateSystem=t.coordinateSystem,this.updateCoordinateSystem());let[s,r,o,c,l,h]=this.children,u=t.getRenderTarget(),d=t.getActiveCubeFace(),f=t.getActiveMipmapLevel(),b=t.xr.enabled;t.xr.enabled=!1;let _=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let m=!1;t.isWebGLRenderer===!0?m=t.state.buffers.depth.getReversed():m=t.reversedDepthBuffer,t.setRenderTarget(n,0,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,s),t.setRenderTarget(n,1,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,r),t.setRenderTarget(n,2,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,o),t.setRenderTarget(n,3,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,c),t.setRenderTarget(n,4,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,l),n.texture.mipmapsAutoUpdate=_,t.setRenderTarget(n,5,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,h),t.setRenderTarget(u,d,f),t.xr.enabled=b,n.texture.needsPMREMUpdate=!0}},fc=class extends pn{constructor(t=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=t,this.perCameraFrustumCulled=!1}},od="\\[\\]\\.:\\/",kb=new RegExp("["+od+"]","g"),cd="[^"+od+"]",zb="[^"+od.replace("\\.","")+"]",Vb=/((?:WC+[\/:])*)/.source.replace("WC",cd),Hb=/(WCOD+)?/.source.replace("WCOD",zb),Gb=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",cd),Wb=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",cd),jb=new RegExp("^"+Vb+Hb+Gb+Wb+"$"),Xb=["material","materials","bones","map"],Ch=class{constructor(t,e,n){let a=n||Ae.parseTrackName(e);this._targetGroup=t,this._bindings=t.subscribe_(e,a)}getValue(t,e){this.bind();let n=this._targetGroup.nCachedObjects_,a=this._bindings[n];a!==void 0&&a.getValue(t,e)}setValue(t,e){let n=this._bindings;for(let a=this._targetGroup.nCachedObjects_,s=n.length;a!==s;++a)n[a].setValue(t,e)}bind(){let t=this._bindings;for(let e=this._targetGroup.nCachedObjects_,n=t.length;e!==n;++e)t[e].bind()}unbind(){let t=this._bindings;for(let e=this._targetGroup.nCachedObjects_,n=t.length;e!==n;++e)t[e].unbind()}},Ae=class i{constructor(t,e,n){this.path=e,this.parsedPath=n||i.parseTrackName(e),this.node=i.findNode(t,this.parsedPath.nodeName),this.rootNode=t,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(t,e,n){return t&&t.isAnimationObjectGroup?new i.Composite(t,e,n):new i(t,e,n)}static sanitizeNodeName(t){return t.replace(/\s/g,"_").replace(kb,"")}static parseTrackName(t){let e=jb.exec(t);if(e===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+t);let n={nodeName:e[2],objectName:e[3],objectIndex:e[4],propertyName:e[5],propertyIndex:e[6]},a=n.nodeName&&n.nodeName.lastIndexOf(".");if(a!==void 0&&a!==-1){let s=n.nodeName.substring(a+1);Xb.indexOf(s)!==-1&&(n.nodeName=n.nodeName.substring(0,a),n.objectName=s)}if(n.propertyName===null||n.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+t);return n}static findNode(t,e){if(e===void 0||e===""||e==="."||e===-1||e===t.name||e===t.uuid)return t;if(t.skeleton){let n=t.skeleton.getBoneByName(e);if(n!==void 0)return n}if(t.children){let n=function(s){for(let r=0;r<s.length;r++){let o=s[r];if(o.name===e||o.uuid===e)return o;let c=n(o.children);if(c)return c}return null},a=n(t.children);if(a)return a}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(t,e){t[e]=this.targetObject[this.propertyName]}_getValue_array(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)t[e++]=n[a]}_getValue_arrayElement(t,e){t[e]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(t,e){this.resolvedProperty.toArray(t,e)}_setValue_direct(t,e){this.targetObject[this.propertyName]=t[e]}_setValue_direct_setNeedsUpdate(t,e){this.targetObject[this.propertyName]=t[e],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(t,e){this.targetObject[this.propertyName]=t[e],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++]}_setValue_array_setNeedsUpdate(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(t,e){this.resolvedProperty[this.propertyIndex]=t[e]}_setValue_arrayElement_setNeedsUpdate(t,e){this.resolvedProperty[this.propertyIndex]=t[e],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(t,e){this.resolvedProperty[this.propertyIndex]=t[e],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(t,e){this.resolvedProperty.fromArray(t,e)}_setValue_fromArray_setNeedsUpdate(t,e){this.resolvedProperty.fromArray(t,e),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(t,e){this.resolvedProperty.fromArray(t,e),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(t,e){this.bind(),this.getValue(t,e)}_setValue_unbound(t,e){this.bind(),this.setValue(t,e)}bind(){let t=this.node,e=this.parsedPath,n=e.objectName,a=e.propertyName,s=e.propertyIndex;if(t||(t=i.findNode(this.rootNode,e.nodeName),this.node=t),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!t){Dt("PropertyBinding: No target node found for track: "+this.path+".");return}if(n){let l=e.objectIndex;switch(n){case"materials":if(!t.material){Ft("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!t.material.materials){Ft("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}t=t.material.materials;break;case"bones":if(!t.skeleton){Ft("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}t=t.skeleton.bones;for(let h=0;h<t.length;h++)if(t[h].name===l){l=h;break}break;case"map":if("map"in t){t=t.map;break}if(!t.material){Ft("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!t.material.map){Ft("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}t=t.material.map;break;default:if(t[n]===void 0){Ft("PropertyBinding: Can not bind to objectName of node undefined.",this);return}t=t[n]}if(l!==void 0){if(t[l]===void 0){Ft("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,t);return}t=t[l]}}let r=t[a];if(r===void 0){let l=e.nodeName;Ft("PropertyBinding: Trying to update property for track: "+l+"."+a+" but it wasn't found.",t);return}let o=this.Versioning.None;this.targetObject=t,t.isMaterial===!0?o=this.Versioning.NeedsUpdate:t.isObject3D===!0&&(o=this.Versioning.MatrixWorldNeedsUpdate);let c=this.BindingType.Direct;if(s!==void 0){if(a==="morphTargetInfluences"){if(!t.geometry){Ft("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!t.geometry.morphAttributes){Ft("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}t.morphTargetDictionary[s]!==void 0&&(s=t.morphTargetDictionary[s])}c=this.BindingType.ArrayElement,this.resolvedProperty=r,this.propertyIndex=s}else r.fromArray!==void 0&&r.toArray!==void 0?(c=this.BindingType.HasFromToArray,this.resolvedProperty=r):Array.isArray(r)?(c=this.BindingType.EntireArray,this.resolvedProperty=r):this.propertyName=a;this.getValue=this.GetterByBindingType[c],this.setValue=this.SetterByBindingTypeAndVersioning[c][o]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};Ae.Composite=Ch;Ae.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};Ae.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};Ae.prototype.GetterByBindingType=[Ae.prototype._getValue_direct,Ae.prototype._getValue_array,Ae.prototype._getValue_arrayElement,Ae.prototype._getValue_toArray];Ae.prototype.SetterByBindingTypeAndVersioning=[[Ae.prototype._setValue_direct,Ae.prototype._setValue_direct_setNeedsUpdate,Ae.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[Ae.prototype._setValue_array,Ae.prototype._setValue_array_setNeedsUpdate,Ae.prototype._setValue_array_setMatrixWorldNeedsUpdate],[Ae.prototype._setValue_arrayElement,Ae.prototype._setValue_arrayElement_setNeedsUpdate,Ae.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[Ae.prototype._setValue_fromArray,Ae.prototype._setValue_fromArray_setNeedsUpdate,Ae.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];xS=new Float32Array(1),Xi=class extends Jo{constructor(t,e,n=1){super(t,e),this.isInstancedInterleavedBuffer=!0,this.meshPerAttribute=n}copy(t){return super.copy(t),this.meshPerAttribute=t.meshPerAttribute,this}clone(t){let e=super.clone(t);return e.meshPerAttribute=this.meshPerAttribute,e}toJSON(t){let e=super.toJSON(t);return e.isInstancedInterleavedBuffer=!0,e.meshPerAttribute=this.meshPerAttribute,e}},cf=new se,Mr=class{constructor(t,e,n=0,a=1/0){this.ray=new Jn(t,e),this.near=n,this.far=a,this.camera=null,this.layers=new Za,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(t,e){this.ray.set(t,e)}setFromCamera(t,e){e.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(t.x,t.y,.5).unproject(e).sub(this.ray.origin).normalize(),this.camera=e):e.isOrthographicCamera?(this.ray.origin.set(t.x,t.y,e.projectionMatrix.elements[14]).unproject(e),this.ray.direction.set(0,0,-1).transformDirection(e.matrixWorld),this.camera=e):Ft("Raycaster: Unsupported camera type: "+e.type)}setFromXRController(t){return cf.identity().extractRotation(t.matrixWorld),this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(cf),this}intersectObject(t,e=!0,n=[]){return Nh(t,this,n,e),n.sort(lf),n}intersectObjects(t,e=!0,n=[]){for(let a=0,s=t.length;a<s;a++)Nh(t[a],this,n,e);return n.sort(lf),n}};as=class{constructor(t=1,e=0,n=0){this.radius=t,this.phi=e,this.theta=n}set(t,e,n){return this.radius=t,this.phi=e,this.theta=n,this}copy(t){return this.radius=t.radius,this.phi=t.phi,this.theta=t.theta,this}makeSafe(){return this.phi=zt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(t){return this.setFromCartesianCoords(t.x,t.y,t.z)}setFromCartesianCoords(t,e,n){return this.radius=Math.sqrt(t*t+e*e+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(t,n),this.phi=Math.acos(zt(e/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}},pd=class pd{constructor(t,e,n,a){this.elements=[1,0,0,1],t!==void 0&&this.set(t,e,n,a)}identity(){return this.set(1,0,0,1),this}fromArray(t,e=0){for(let n=0;n<4;n++)this.elements[n]=t[n+e];return this}set(t,e,n,a){let s=this.elements;return s[0]=t,s[2]=e,s[1]=n,s[3]=a,this}};pd.prototype.isMatrix2=!0;Ph=pd,hf=new k,Lo=new k,Ga=new k,Wa=new k,Mh=new k,qb=new k,Yb=new k,ga=class{constructor(t=new k,e=new k){this.start=t,this.end=e}set(t,e){return this.start.copy(t),this.end.copy(e),this}copy(t){return this.start.copy(t.start),this.end.copy(t.end),this}getCenter(t){return t.addVectors(this.start,this.end).multiplyScalar(.5)}delta(t){return t.subVectors(this.end,this.start)}distanceSq(){return this.start.distanceToSquared(this.end)}distance(){return this.start.distanceTo(this.end)}at(t,e){return this.delta(e).multiplyScalar(t).add(this.start)}closestPointToPointParameter(t,e){hf.subVectors(t,this.start),Lo.subVectors(this.end,this.start);let n=Lo.dot(Lo);if(n===0)return 0;let s=Lo.dot(hf)/n;return e&&(s=zt(s,0,1)),s}closestPointToPoint(t,e,n){let a=this.closestPointToPointParameter(t,e);return this.delta(n).multiplyScalar(a).add(this.start)}distanceSqToLine3(t,e=qb,n=Yb){let a=10000000000000001e-32,s,r,o=this.start,c=t.start,l=this.end,h=t.end;Ga.subVectors(l,o),Wa.subVectors(h,c),Mh.subVectors(o,c);let u=Ga.dot(Ga),d=Wa.dot(Wa),f=Wa.dot(Mh);if(u<=a&&d<=a)return e.copy(o),n.copy(c),e.distanceToSquared(n);if(u<=a)s=0,r=f/d,r=zt(r,0,1);else{let b=Ga.dot(Mh);if(d<=a)r=0,s=zt(-b/u,0,1);else{let _=Ga.dot(Wa),m=u*d-_*_;m!==0?s=zt((_*f-b*d)/m,0,1):s=0,r=(_*s+f)/d,r<0?(r=0,s=zt(-b/u,0,1)):r>1&&(r=1,s=zt((_-b)/u,0,1))}}return e.copy(o).addScaledVector(Ga,s),n.copy(c).addScaledVector(Wa,r),e.distanceToSquared(n)}applyMatrix4(t){return this.start.applyMatrix4(t),this.end.applyMatrix4(t),this}equals(t){return t.start.equals(this.start)&&t.end.equals(this.end)}clone(){return new this.constructor().copy(this)}},Sr=class extends ts{constructor(t=10,e=10,n=4473924,a=8947848){n=new Ht(n),a=new Ht(a);let s=e/2,r=t/e,o=t/2,c=[],l=[];for(let d=0,f=0,b=-o;d<=e;d++,b+=r){c.push(-o,0,b,o,0,b),c.push(b,0,-o,b,0,o);let _=d===s?n:a;_.toArray(l,f),f+=3,_.toArray(l,f),f+=3,_.toArray(l,f),f+=3,_.toArray(l,f),f+=3}let h=new Le;h.setAttribute("position",new me(c,3)),h.setAttribute("color",new me(l,3));let u=new pa({vertexColors:!0,toneMapped:!1});super(h,u),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}},wr=class extends qn{constructor(t,e=null){super(),this.object=t,this.domElement=e,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(t){this.domElement!==null&&this.disconnect(),this.domElement=t}disconnect(){}dispose(){}update(){}};typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?Dt("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187")});function bp(){let i=null,t=!1,e=null,n=null;function a(s,r){n=i.requestAnimationFrame(a),e(s,r)}return{start:function(){t!==!0&&e!==null&&i!==null&&(n=i.requestAnimationFrame(a),t=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),t=!1},setAnimationLoop:function(s){e=s},setContext:function(s){i=s}}}function Kb(i){let t=new WeakMap;function e(o,c){let l=o.array,h=o.usage,u=l.byteLength,d=i.createBuffer();i.bindBuffer(c,d),i.bufferData(c,l,h),o.onUploadCallback();let f;if(l instanceof Float32Array)f=i.FLOAT;else if(typeof Float16Array<"u"&&l instanceof Float16Array)f=i.HALF_FLOAT;else if(l instanceof Uint16Array)o.isFloat16BufferAttribute?f=i.HALF_FLOAT:f=i.UNSIGNED_SHORT;else if(l instanceof Int16Array)f=i.SHORT;else if(l instanceof Uint32Array)f=i.UNSIGNED_INT;else if(l instanceof Int32Array)f=i.INT;else if(l instanceof Int8Array)f=i.BYTE;else if(l instanceof Uint8Array)f=i.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)f=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:d,type:f,bytesPerElement:l.BYTES_PER_ELEMENT,version:o.version,size:u}}function n(o,c,l){let h=c.array,u=c.updateRanges;if(i.bindBuffer(l,o),u.length===0)i.bufferSubData(l,0,h);else{u.sort((f,b)=>f.start-b.start);let d=0;for(let f=1;f<u.length;f++){let b=u[d],_=u[f];_.start<=b.start+b.count+1?b.count=Math.max(b.count,_.start+_.count-b.start):(++d,u[d]=_)}u.length=d+1;for(let f=0,b=u.length;f<b;f++){let _=u[f];i.bufferSubData(l,_.start*h.BYTES_PER_ELEMENT,h,_.start,_.count)}c.clearUpdateRanges()}c.onUploadCallback()}function a(o){return o.isInterleavedBufferAttribute&&(o=o.data),t.get(o)}function s(o){o.isInterleavedBufferAttribute&&(o=o.data);let c=t.get(o);c&&(i.deleteBuffer(c.buffer),t.delete(o))}function r(o,c){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){let h=t.get(o);(!h||h.version<o.version)&&t.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}let l=t.get(o);if(l===void 0)t.set(o,e(o,c));else if(l.version<o.version){if(l.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(l.buffer,o,c),l.version=o.version}}return{get:a,remove:s,update:r}}function Ny(i,t,e,n,a,s){let r=new Ht(0),o=a===!0?0:1,c,l,h=null,u=0,d=null;function f(v){let w=v.isScene===!0?v.background:null;if(w&&w.isTexture){let p=v.backgroundBlurriness>0;w=t.get(w,p)}return w}function b(v){let w=!1,p=f(v);p===null?m(r,o):p&&p.isColor&&(m(p,1),w=!0);let y=i.xr.getEnvironmentBlendMode();y==="additive"?e.buffers.color.setClear(0,0,0,1,s):y==="alpha-blend"&&e.buffers.color.setClear(0,0,0,0,s),(i.autoClear||w)&&(e.buffers.depth.setTest(!0),e.buffers.depth.setMask(!0),e.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function _(v,w){let p=f(w);p&&p.isCubeTexture?(l===void 0&&(l=new an(new es(1,1,1),new Fn({name:"BackgroundCubeMaterial",uniforms:Sa(yn.backgroundCube.uniforms),vertexShader:yn.backgroundCube.vertexShader,fragmentShader:yn.backgroundCube.fragmentShader,side:Xe,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),l.geometry.deleteAttribute("uv"),l.onBeforeRender=function(y,S,g){this.matrixWorld.copyPosition(g.matrixWorld)},Object.defineProperty(l.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(l)),l.material.uniforms.envMap.value=p,l.material.uniforms.backgroundBlurriness.value=w.backgroundBlurriness,l.material.uniforms.backgroundIntensity.value=w.backgroundIntensity,l.material.uniforms.backgroundRotation.value.setFromMatrix4(Cy.makeRotationFromEuler(w.backgroundRotation)).transpose(),p.isRenderTargetTexture===!1&&l.material.uniforms.backgroundRotation.value.premultiply(xp),l.material.toneMapped=Jt.getTransfer(p.colorSpace)!==ue,(h!==p||u!==p.version||d!==i.toneMapping)&&(l.material.needsUpdate=!0,h=p,u=p.version,d=i.toneMapping),l.layers.enableAll(),v.unshift(l,l.geometry,l.material,0,0,null)):p&&p.isTexture&&(c===void 0&&(c=new an(new hr(2,2),new Fn({name:"BackgroundMaterial",uniforms:Sa(yn.background.uniforms),vertexShader:yn.background.vertexShader,fragmentShader:yn.background.fragmentShader,side:oi,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),Object.defineProperty(c.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(c)),c.material.uniforms.t2D.value=p,c.material.uniforms.backgroundIntensity.value=w.backgroundIntensity,c.material.toneMapped=Jt.getTransfer(p.colorSpace)!==ue,p.matrixAutoUpdate===!0&&p.updateMatrix(),c.material.uniforms.uvTransform.value.copy(p.matrix),(h!==p||u!==p.version||d!==i.toneMapping)&&(c.material.needsUpdate=!0,h=p,u=p.version,d=i.toneMapping),c.layers.enableAll(),v.unshift(c,c.geometry,c.material,0,0,null))}function m(v,w){v.getRGB(tl,rd(i)),e.buffers.color.setClear(tl.r,tl.g,tl.b,w,s)}function x(){l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0),c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0)}return{getClearColor:function(){return r},setClearColor:function(v,w=1){r.set(v),o=w,m(r,o)},getClearAlpha:function(){return o},setClearAlpha:function(v){o=v,m(r,o)},render:b,addToRenderList:_,dispose:x}}function Py(i,t){let e=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},a=d(null),s=a,r=!1;function o(I,C,P,N,U){let z=!1,F=u(I,N,P,C);s!==F&&(s=F,l(s.object)),z=f(I,N,P,U),z&&b(I,N,P,U),U!==null&&t.update(U,i.ELEMENT_ARRAY_BUFFER),(z||r)&&(r=!1,p(I,C,P,N),U!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,t.get(U).buffer))}function c(){return i.createVertexArray()}function l(I){return i.bindVertexArray(I)}function h(I){return i.deleteVertexArray(I)}function u(I,C,P,N){let U=N.wireframe===!0,z=n[C.id];z===void 0&&(z={},n[C.id]=z);let F=I.isInstancedMesh===!0?I.id:0,K=z[F];K===void 0&&(K={},z[F]=K);let H=K[P.id];H===void 0&&(H={},K[P.id]=H);let J=H[U];return J===void 0&&(J=d(c()),H[U]=J),J}function d(I){let C=[],P=[],N=[];for(let U=0;U<e;U++)C[U]=0,P[U]=0,N[U]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:C,enabledAttributes:P,attributeDivisors:N,object:I,attributes:{},index:null}}function f(I,C,P,N){let U=s.attributes,z=C.attributes,F=0,K=P.getAttributes();for(let H in K)if(K[H].location>=0){let tt=U[H],ft=z[H];if(ft===void 0&&(H==="instanceMatrix"&&I.instanceMatrix&&(ft=I.instanceMatrix),H==="instanceColor"&&I.instanceColor&&(ft=I.instanceColor)),tt===void 0||tt.attribute!==ft||ft&&tt.data!==ft.data)return!0;F++}return s.attributesNum!==F||s.index!==N}function b(I,C,P,N){let U={},z=C.attributes,F=0,K=P.getAttributes();for(let H in K)if(K[H].location>=0){let tt=z[H];tt===void 0&&(H==="instanceMatrix"&&I.instanceMatrix&&(tt=I.instanceMatrix),H==="instanceColor"&&I.instanceColor&&(tt=I.instanceColor));let ft={};ft.attribute=tt,tt&&tt.data&&(ft.data=tt.data),U[H]=ft,F++}s.attributes=U,s.attributesNum=F,s.index=N}function _(){let I=s.newAttributes;for(let C=0,P=I.length;C<P;C++)I[C]=0}function m(I){x(I,0)}function x(I,C){let P=s.newAttributes,N=s.enabledAttributes,U=s.attributeDivisors;P[I]=1,N[I]===0&&(i.enableVertexAttribArray(I),N[I]=1),U[I]!==C&&(i.vertexAttribDivisor(I,C),U[I]=C)}function v(){let I=s.newAttributes,C=s.enabledAttributes;for(let P=0,N=C.length;P<N;P++)C[P]!==I[P]&&(i.disableVertexAttribArray(P),C[P]=0)}function w(I,C,P,N,U,z,F){F===!0?i.vertexAttribIPointer(I,C,P,U,z):i.vertexAttribPointer(I,C,P,N,U,z)}function p(I,C,P,N){_();let U=N.attributes,z=P.getAttributes(),F=C.defaultAttributeValues;for(let K in z){let H=z[K];if(H.location>=0){let J=U[K];if(J===void 0&&(K==="instanceMatrix"&&I.instanceMatrix&&(J=I.instanceMatrix),K==="instanceColor"&&I.instanceColor&&(J=I.instanceColor)),J!==void 0){let tt=J.normalized,ft=J.itemSize,Ct=t.get(J);if(Ct===void 0)continue;let q=Ct.buffer,st=Ct.type,xt=Ct.bytesPerElement,It=st===i.INT||st===i.UNSIGNED_INT||J.gpuType===cs;if(J.isInterleavedBufferAttribute){let mt=J.data,Ot=mt.isInterleavedBuffer===!0?mt.stride:mt.itemSize,Me=J.offset;if(mt.isInstancedInterleavedBuffer||mt.isInstancedBufferAttribute){for(let Lt=0;Lt<H.locationSize;Lt++)x(H.location+Lt,mt.meshPerAttribute);I.isInstancedMesh!==!0&&N._maxInstanceCount===void 0&&(N._maxInstanceCount=mt.meshPerAttribute*mt.count)}else for(let Lt=0;Lt<H.locationSize;Lt++)m(H.location+Lt);i.bindBuffer(i.ARRAY_BUFFER,q);for(let Lt=0;Lt<H.locationSize;Lt++)w(H.location+Lt,ft/H.locationSize,st,tt,Ot*xt,(Me+ft/H.locationSize*Lt)*xt,It)}else{if(J.isInstancedBufferAttribute){for(let mt=0;mt<H.locationSize;mt++)x(H.location+mt,J.meshPerAttribute);I.isInstancedMesh!==!0&&N._maxInstanceCount===void 0&&(N._maxInstanceCount=J.meshPerAttribute*J.count)}else for(let mt=0;mt<H.locationSize;mt++)m(H.location+mt);i.bindBuffer(i.ARRAY_BUFFER,q);for(let mt=0;mt<H.locationSize;mt++)w(H.location+mt,ft/H.locationSize,st,tt,ft*xt,ft/H.locationSize*mt*xt,It)}}else if(F!==void 0){let tt=F[K];if(tt!==void 0)switch(tt.length){case 2:i.vertexAttrib2fv(H.location,tt);break;case 3:i.vertexAttrib3fv(H.location,tt);break;case 4:i.vertexAttrib4fv(H.location,tt);break;default:i.vertexAttrib1fv(H.location,tt)}}}}v()}function y(){E();for(let I in n){let C=n[I];for(let P in C){let N=C[P];for(let U in N){let z=N[U];for(let F in z)h(z[F].object),delete z[F];delete N[U]}}delete n[I]}}function S(I){if(n[I.id]===void 0)return;let C=n[I.id];for(let P in C){let N=C[P];for(let U in N){let z=N[U];for(let F in z)h(z[F].object),delete z[F];delete N[U]}}delete n[I.id]}function g(I){for(let C in n){let P=n[C];for(let N in P){let U=P[N];if(U[I.id]===void 0)continue;let z=U[I.id];for(let F in z)h(z[F].object),delete z[F];delete U[I.id]}}}function M(I){for(let C in n){let P=n[C],N=I.isInstancedMesh===!0?I.id:0,U=P[N];if(U!==void 0){for(let z in U){let F=U[z];for(let K in F)h(F[K].object),delete F[K];delete U[z]}delete P[N],Object.keys(P).length===0&&delete n[C]}}}function E(){A(),r=!0,s!==a&&(s=a,l(s.object))}function A(){a.geometry=null,a.program=null,a.wireframe=!1}return{setup:o,reset:E,resetDefaultState:A,dispose:y,releaseStatesOfGeometry:S,releaseStatesOfObject:M,releaseStatesOfProgram:g,initAttributes:_,enableAttribute:m,disableUnusedAttributes:v}}function Ly(i,t,e){let n;function a(c){n=c}function s(c,l){i.drawArrays(n,c,l),e.update(l,n,1)}function r(c,l,h){h!==0&&(i.drawArraysInstanced(n,c,l,h),e.update(l,n,h))}function o(c,l,h){if(h===0)return;t.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,c,0,l,0,h);let d=0;for(let f=0;f<h;f++)d+=l[f];e.update(d,n,1)}this.setMode=a,this.render=s,this.renderInstances=r,this.renderMultiDraw=o}function Dy(i,t,e,n){let a;function s(){if(a!==void 0)return a;if(t.has("EXT_texture_filter_anisotropic")===!0){let g=t.get("EXT_texture_filter_anisotropic");a=i.getParameter(g.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else a=0;return a}function r(g){return!(g!==xn&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(g){let M=g===Kn&&(t.has("EXT_color_buffer_half_float")||t.has("EXT_color_buffer_float"));return!(g!==sn&&g!==bn&&!M&&n.convert(g)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function c(g){if(g==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";g="mediump"}return g==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=e.precision!==void 0?e.precision:"highp",h=c(l);h!==l&&(Dt("WebGLRenderer:",l,"not supported, using",h,"instead."),l=h);let u=e.reversedDepthBuffer===!0&&t.has("EXT_clip_control"),d=e.logarithmicDepthBuffer===!0&&u===!1;e.reversedDepthBuffer===!0&&u===!1&&Dt("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),e.logarithmicDepthBuffer===!0&&u===!0&&Dt("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let f=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),b=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),_=i.getParameter(i.MAX_TEXTURE_SIZE),m=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),x=i.getParameter(i.MAX_VERTEX_ATTRIBS),v=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),w=i.getParameter(i.MAX_VARYING_VECTORS),p=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),y=i.getParameter(i.MAX_SAMPLES),S=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:s,getMaxPrecision:c,textureFormatReadable:r,textureTypeReadable:o,precision:l,logarithmicDepthBuffer:d,reversedDepthBuffer:u,maxTextures:f,maxVertexTextures:b,maxTextureSize:_,maxCubemapSize:m,maxAttributes:x,maxVertexUniforms:v,maxVaryings:w,maxFragmentUniforms:p,maxSamples:y,samples:S}}function Uy(i){let t=this,e=null,n=0,a=!1,s=!1,r=new fn,o=new Bt,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(u,d){let f=u.length!==0||d||n!==0||a;return a=d,n=u.length,f},this.beginShadows=function(){s=!0,h(null)},this.endShadows=function(){s=!1},this.setGlobalState=function(u,d){e=h(u,d,0)},this.setState=function(u,d,f){let b=u.clippingPlanes,_=u.clipIntersection,m=u.clipShadows,x=i.get(u);if(!a||b===null||b.length===0||s&&!m)s?h(null):l();else{let v=s?0:n,w=v*4,p=x.clippingState||null;c.value=p,p=h(b,d,w,f);for(let y=0;y!==w;++y)p[y]=e[y];x.clippingState=p,this.numIntersection=_?this.numPlanes:0,this.numPlanes+=v}};function l(){c.value!==e&&(c.value=e,c.needsUpdate=n>0),t.numPlanes=n,t.numIntersection=0}function h(u,d,f,b){let _=u!==null?u.length:0,m=null;if(_!==0){if(m=c.value,b!==!0||m===null){let x=f+_*4,v=d.matrixWorldInverse;o.getNormalMatrix(v),(m===null||m.length<x)&&(m=new Float32Array(x));for(let w=0,p=f;w!==_;++w,p+=4)r.copy(u[w]).applyMatrix4(v,o),r.normal.toArray(m,p),m[p+3]=r.constant}c.value=m,c.needsUpdate=!0}return t.numPlanes=_,t.numIntersection=0,m}}function Zf(i,t,e){return new kr(i,{minFilter:Ci,generateMipmaps:t,type:Kn,colorSpace:Ys,depthBuffer:e})}function zr(i,t,e){return new Fn({name:i,uniforms:t,vertexShader:jt.cube_vert,fragmentShader:e,side:Xe,blending:ba,depthTest:!1,depthWrite:!1})}function Vy(){return zr("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${yp}u

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
	`)}function Hy(){return zr("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:_p}},`

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
	`)}function Gy(){return zr("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${Fy}
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
	`)}function Qf(){return zr("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

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
	`)}function $f(){return zr("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function Wy(i){let t=new WeakMap,e=new WeakMap,n=null;function a(d,f=!1){return d==null?null:f?r(d):s(d)}function s(d){if(d&&d.isTexture){let f=d.mapping;if(f===bc||f===xc)if(t.has(d)){let b=t.get(d).texture;return o(b,d.mapping)}else{let b=d.image;if(b&&b.height>0){let _=new kr(b.height);return _.fromEquirectangularTexture(i,d),t.set(d,_),d.addEventListener("dispose",l),o(_.texture,d.mapping)}else return null}}return d}function r(d){if(d&&d.isTexture&&d.isPMREMTexture!==!0){let f=d.mapping,b=f===bc||f===xc,_=f===ya||f===os;if(b||_){let m=e.get(d),x=m!==void 0?m.texture.pmremVersion:0;if(d.isRenderTargetTexture&&d.pmremVersion!==x)return n===null&&(n=new nl(i)),m=b?n.fromEquirectangular(d,m):n.fromCubemap(d,m),m.texture.pmremVersion=d.pmremVersion,e.set(d,m),m.texture;if(m!==void 0)return m.texture;{let v=d.image;return b&&v&&v.height>0||_&&v&&c(v)?(n===null&&(n=new nl(i)),m=b?n.fromEquirectangular(d):n.fromCubemap(d),m.texture.pmremVersion=d.pmremVersion,e.set(d,m),d.addEventListener("dispose",h),m.texture):null}}}return d}function o(d,f){return f===bc?d.mapping=ya:f===xc&&(d.mapping=os),d}function c(d){let f=0,b=6;for(let _=0;_<b;_++)d[_]!==void 0&&f++;return f===b}function l(d){let f=d.target;f.removeEventListener("dispose",l);let b=t.get(f);b!==void 0&&(t.delete(f),b.dispose())}function h(d){let f=d.target;f.removeEventListener("dispose",h);let b=e.get(f);b!==void 0&&(e.delete(f),b.dispose())}function u(){t=new WeakMap,e=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:a,dispose:u}}function jy(i){let t={};function e(n){if(t[n]!==void 0)return t[n];let a=i.getExtension(n);return t[n]=a,a}return{has:function(n){return e(n)!==null},init:function(){e("EXT_color_buffer_float"),e("WEBGL_clip_cull_distance"),e("OES_texture_float_linear"),e("EXT_color_buffer_half_float"),e("WEBGL_multisampled_render_to_texture"),e("WEBGL_render_shared_exponent")},get:function(n){let a=e(n);return a===null&&Ws("WebGLRenderer: "+n+" extension not supported."),a}}}function Xy(i,t,e,n){let a={},s=new WeakMap,r=new FinalizationRegistry(b=>delete a[b]);function o(b){c(b.target)}function c(b){b.index!==null&&t.remove(b.index);for(let m in b.attributes)t.remove(b.attributes[m]);b.removeEventListener("dispose",o),delete a[b.id],r.unregister(b);let _=s.get(b);_&&(t.remove(_),s.delete(b)),n.releaseStatesOfGeometry(b),b.isInstancedBufferGeometry===!0&&delete b._maxInstanceCount,e.memory.geometries--}function l(b,_){return a[_.id]!==void 0||(_.addEventListener("dispose",o),a[_.id]=new WeakRef(_),r.register(_,_.id,_),e.memory.geometries++),_}function h(b){let _=b.attributes;for(let m in _)t.update(_[m],i.ARRAY_BUFFER)}function u(b){let _=b.index,m=b.attributes.position,x=0;if(m===void 0)return;let v=_!==null?_.array.length:m.array.length/3-1,w=m.count>=65535?er:tr,p=new w(Math.ceil(v/3)*6,1),y=p.array;if(_!==null){let g=_.array;x=_.version;for(let M=0,E=0;M<v;M+=3){let A=g[M+0],I=g[M+1],C=g[M+2];y[E++]=A,y[E++]=I,y[E++]=I,y[E++]=C,y[E++]=C,y[E++]=A}}else{x=m.version;for(let g=0,M=0;g<v;g+=3){let E=g+0,A=g+1,I=g+2;y[M++]=E,y[M++]=A,y[M++]=A,y[M++]=I,y[M++]=I,y[M++]=E}}p.version=x;let S=s.get(b);S&&t.remove(S),s.set(b,p)}function d(b){let _=s.get(b);if(_){let m=b.index;m!==null&&_.version<m.version&&u(b)}else u(b);return s.get(b)}function f(){for(let b in a){let _=a[b].deref();_!==void 0&&c(_)}}return{get:l,update:h,getWireframeAttribute:d,dispose:f}}function qy(i,t,e){let n;function a(u){n=u}let s,r;function o(u){s=u.type,r=u.bytesPerElement}function c(u,d){i.drawElements(n,d,s,u*r),e.update(d,n,1)}function l(u,d,f){f!==0&&(i.drawElementsInstanced(n,d,s,u*r,f),e.update(d,n,f))}function h(u,d,f){if(f===0)return;t.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,d,0,s,u,0,f);let _=0;for(let m=0;m<f;m++)_+=d[m];e.update(_,n,1)}this.setMode=a,this.setIndex=o,this.render=c,this.renderInstances=l,this.renderMultiDraw=h}function Yy(i){let t={geometries:0,textures:0},e={frame:0,calls:0,triangles:0,points:0,lines:0};function n(s,r,o){switch(e.calls++,r){case i.TRIANGLES:e.triangles+=o*(s/3);break;case i.LINES:e.lines+=o*(s/2);break;case i.LINE_STRIP:e.lines+=o*(s-1);break;case i.LINE_LOOP:e.lines+=o*s;break;case i.POINTS:e.points+=o*s;break;default:Ft("WebGLInfo: Unknown draw mode:",r);break}}function a(){e.calls=0,e.triangles=0,e.points=0,e.lines=0}return{memory:t,render:e,programs:null,autoReset:!0,reset:a,update:n}}function Jy(i,t,e){let n=new WeakMap,a=new re;function s(r,o,c){let l=r.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,u=h!==void 0?h.length:0,d=n.get(o);if(d===void 0||d.count!==u){let E=function(){g.dispose(),n.delete(o),o.removeEventListener("dispose",E)};d!==void 0&&d.texture.dispose();let f=o.morphAttributes.position!==void 0,b=o.morphAttributes.normal!==void 0,_=o.morphAttributes.color!==void 0,m=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],v=o.morphAttributes.color||[],w=0;f===!0&&(w=1),b===!0&&(w=2),_===!0&&(w=3);let p=o.attributes.position.count*w,y=1;p>t.maxTextureSize&&(y=Math.ceil(p/t.maxTextureSize),p=t.maxTextureSize);let S=new Float32Array(p*y*4*u),g=new Qs(S,p,y,u);g.type=bn,g.needsUpdate=!0;let M=w*4;for(let A=0;A<u;A++){let I=m[A],C=x[A],P=v[A],N=p*y*4*A;for(let U=0;U<I.count;U++){let z=U*M;f===!0&&(a.fromBufferAttribute(I,U),S[N+z+0]=a.x,S[N+z+1]=a.y,S[N+z+2]=a.z,S[N+z+3]=0),b===!0&&(a.fromBufferAttribute(C,U),S[N+z+4]=a.x,S[N+z+5]=a.y,S[N+z+6]=a.z,S[N+z+7]=0),_===!0&&(a.fromBufferAttribute(P,U),S[N+z+8]=a.x,S[N+z+9]=a.y,S[N+z+10]=a.z,S[N+z+11]=P.itemSize===4?a.w:1)}}d={count:u,texture:g,size:new Ut(p,y)},n.set(o,d),o.addEventListener("dispose",E)}if(r.isInstancedMesh===!0&&r.morphTexture!==null)c.getUniforms().setValue(i,"morphTexture",r.morphTexture,e);else{let f=0;for(let _=0;_<l.length;_++)f+=l[_];let b=o.morphTargetsRelative?1:1-f;c.getUniforms().setValue(i,"morphTargetBaseInfluence",b),c.getUniforms().setValue(i,"morphTargetInfluences",l)}c.getUniforms().setValue(i,"morphTargetsTexture",d.texture,e),c.getUniforms().setValue(i,"morphTargetsTextureSize",d.size)}return{update:s}}function Ky(i,t,e,n,a){let s=new WeakMap;function r(l){let h=a.render.frame,u=l.geometry,d=t.get(l,u);if(s.get(d)!==h&&(t.update(d),s.set(d,h)),l.isInstancedMesh&&(l.hasEventListener("dispose",c)===!1&&l.addEventListener("dispose",c),s.get(l)!==h&&(e.update(l.instanceMatrix,i.ARRAY_BUFFER),l.instanceColor!==null&&e.update(l.instanceColor,i.ARRAY_BUFFER),s.set(l,h))),l.isSkinnedMesh){let f=l.skeleton;s.get(f)!==h&&(f.update(),s.set(f,h))}return d}function o(){s=new WeakMap}function c(l){let h=l.target;h.removeEventListener("dispose",c),n.releaseStatesOfObject(h),e.remove(h.instanceMatrix),h.instanceColor!==null&&e.remove(h.instanceColor)}return{update:r,dispose:o}}function Qy(i,t,e,n,a,s){let r=new Cn(t,e,{type:i,depthBuffer:a,stencilBuffer:s,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),o=null,c=null,l=null,h=new Le;h.setAttribute("position",new me([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new me([0,2,0,0,2,0],2));let u=new $o({uniforms:{tDiffuse:{value:null}},vertexShader:`
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
			}`,depthTest:!1,depthWrite:!1}),d=new an(h,u),f=new xr(-1,1,1,-1,0,1),b=null,_=null,m=!1,x,v=null,w=[],p=!1;this.setSize=function(y,S){r.setSize(y,S),o!==null&&o.setSize(y,S),c!==null&&c.setSize(y,S);for(let g=0;g<w.length;g++){let M=w[g];M.setSize&&M.setSize(y,S)}},this.setEffects=function(y){w=y,p=w.length>0&&w[0].isRenderPass===!0;let S=r.width,g=r.height;w.length>0&&o===null&&(o=new Cn(S,g,{type:Kn,depthBuffer:!1,stencilBuffer:!1}),c=new Cn(S,g,{type:Kn,depthBuffer:!1,stencilBuffer:!1}));let M=a===!0&&w.some(E=>E.needsDepthTexture===!0);M!==(r.depthTexture!==null)&&(M===!0&&l===null&&(l=new Ri(S,g),s===!0&&(l.format=Ni,l.type=_a)),r.dispose(),r.depthTexture=M?l:null,r.resolveDepthBuffer=M,r.storeMultisampledDepthBuffer=M);for(let E=0;E<w.length;E++){let A=w[E];A.setSize&&A.setSize(S,g),M&&A.needsDepthTexture===!0&&A.setDepthTexture&&A.setDepthTexture(l)}},this.begin=function(y,S){if(m||y.toneMapping===ci&&w.length===0)return!1;if(v=S,S!==null){let g=S.width,M=S.height;(r.width!==g||r.height!==M)&&this.setSize(g,M)}return p===!1&&y.setRenderTarget(r),x=y.toneMapping,y.toneMapping=ci,!0},this.hasRenderPass=function(){return p},this.end=function(y,S){y.toneMapping=x,m=!0;let g=r,M=o;for(let E=0;E<w.length;E++){let A=w[E];A.enabled!==!1&&(A.render(y,M,g,S),A.needsSwap!==!1&&(g=M,M=M===o?c:o))}if(b!==y.outputColorSpace||_!==y.toneMapping){b=y.outputColorSpace,_=y.toneMapping,u.defines={},Jt.getTransfer(b)===ue&&(u.defines.SRGB_TRANSFER="");let E=Zy[_];E&&(u.defines[E]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=g.texture,y.setRenderTarget(v),y.render(d,f),v=null,m=!1},this.isCompositing=function(){return m},this.dispose=function(){r.dispose(),o!==null&&o.dispose(),c!==null&&c.dispose(),h.dispose(),u.dispose()}}function us(i,t,e){let n=i[0];if(n<=0||n>0)return i;let a=t*e,s=tp[a];if(s===void 0&&(s=new Float32Array(a),tp[a]=s),t!==0){n.toArray(s,0);for(let r=1,o=0;r!==t;++r)o+=e,i[r].toArray(s,o)}return s}function Fe(i,t){if(i.length!==t.length)return!1;for(let e=0,n=i.length;e<n;e++)if(i[e]!==t[e])return!1;return!0}function Be(i,t){for(let e=0,n=t.length;e<n;e++)i[e]=t[e]}function al(i,t){let e=ep[t];e===void 0&&(e=new Int32Array(t),ep[t]=e);for(let n=0;n!==t;++n)e[n]=i.allocateTextureUnit();return e}function $y(i,t){let e=this.cache;e[0]!==t&&(i.uniform1f(this.addr,t),e[0]=t)}function t_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2f(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Fe(e,t))return;i.uniform2fv(this.addr,t),Be(e,t)}}function e_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3f(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else if(t.r!==void 0)(e[0]!==t.r||e[1]!==t.g||e[2]!==t.b)&&(i.uniform3f(this.addr,t.r,t.g,t.b),e[0]=t.r,e[1]=t.g,e[2]=t.b);else{if(Fe(e,t))return;i.uniform3fv(this.addr,t),Be(e,t)}}function n_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4f(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Fe(e,t))return;i.uniform4fv(this.addr,t),Be(e,t)}}function i_(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Fe(e,t))return;i.uniformMatrix2fv(this.addr,!1,t),Be(e,t)}else{if(Fe(e,n))return;ap.set(n),i.uniformMatrix2fv(this.addr,!1,ap),Be(e,n)}}function a_(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Fe(e,t))return;i.uniformMatrix3fv(this.addr,!1,t),Be(e,t)}else{if(Fe(e,n))return;ip.set(n),i.uniformMatrix3fv(this.addr,!1,ip),Be(e,n)}}function s_(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Fe(e,t))return;i.uniformMatrix4fv(this.addr,!1,t),Be(e,t)}else{if(Fe(e,n))return;np.set(n),i.uniformMatrix4fv(this.addr,!1,np),Be(e,n)}}function r_(i,t){let e=this.cache;e[0]!==t&&(i.uniform1i(this.addr,t),e[0]=t)}function o_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2i(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Fe(e,t))return;i.uniform2iv(this.addr,t),Be(e,t)}}function c_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3i(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Fe(e,t))return;i.uniform3iv(this.addr,t),Be(e,t)}}function l_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4i(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Fe(e,t))return;i.uniform4iv(this.addr,t),Be(e,t)}}function h_(i,t){let e=this.cache;e[0]!==t&&(i.uniform1ui(this.addr,t),e[0]=t)}function d_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2ui(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Fe(e,t))return;i.uniform2uiv(this.addr,t),Be(e,t)}}function u_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3ui(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Fe(e,t))return;i.uniform3uiv(this.addr,t),Be(e,t)}}function f_(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4ui(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Fe(e,t))return;i.uniform4uiv(this.addr,t),Be(e,t)}}function sl(i){return i.version===0&&(i.compareFunction=$h,i.needsUpdate=!0),i}function p_(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a);let s;this.type===i.SAMPLER_2D_SHADOW?s=sl(Mp):s=vp,e.setTexture2D(t||s,a)}function m_(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a),e.setTexture3D(t||Ap,a)}function g_(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a);let s;this.type===i.SAMPLER_CUBE_SHADOW?s=sl(Sp):s=Ep,e.setTextureCube(t||s,a)}function b_(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a),e.setTexture2DArray(t||wp,a)}function x_(i){switch(i){case 5126:return $y;case 35664:return t_;case 35665:return e_;case 35666:return n_;case 35674:return i_;case 35675:return a_;case 35676:return s_;case 5124:case 35670:return r_;case 35667:case 35671:return o_;case 35668:case 35672:return c_;case 35669:case 35673:return l_;case 5125:return h_;case 36294:return d_;case 36295:return u_;case 36296:return f_;case 35678:case 36198:case 36298:case 36306:case 35682:return p_;case 35679:case 36299:case 36307:return m_;case 35680:case 36300:case 36308:case 36293:return g_;case 36289:case 36303:case 36311:case 36292:return b_}}function y_(i,t){i.uniform1fv(this.addr,t)}function __(i,t){let e=us(t,this.size,2);i.uniform2fv(this.addr,e)}function v_(i,t){let e=us(t,this.size,3);i.uniform3fv(this.addr,e)}function M_(i,t){let e=us(t,this.size,4);i.uniform4fv(this.addr,e)}function S_(i,t){let e=us(t,this.size,4);i.uniformMatrix2fv(this.addr,!1,e)}function w_(i,t){let e=us(t,this.size,9);i.uniformMatrix3fv(this.addr,!1,e)}function A_(i,t){let e=us(t,this.size,16);i.uniformMatrix4fv(this.addr,!1,e)}function E_(i,t){i.uniform1iv(this.addr,t)}function T_(i,t){i.uniform2iv(this.addr,t)}function I_(i,t){i.uniform3iv(this.addr,t)}function R_(i,t){i.uniform4iv(this.addr,t)}function C_(i,t){i.uniform1uiv(this.addr,t)}function N_(i,t){i.uniform2uiv(this.addr,t)}function P_(i,t){i.uniform3uiv(this.addr,t)}function L_(i,t){i.uniform4uiv(this.addr,t)}function D_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Fe(n,s)||(i.uniform1iv(this.addr,s),Be(n,s));let r;this.type===i.SAMPLER_2D_SHADOW?r=sl(Mp):r=vp;for(let o=0;o!==a;++o)e.setTexture2D(t[o]||r,s[o])}function U_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Fe(n,s)||(i.uniform1iv(this.addr,s),Be(n,s));for(let r=0;r!==a;++r)e.setTexture3D(t[r]||Ap,s[r])}function O_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Fe(n,s)||(i.uniform1iv(this.addr,s),Be(n,s));let r;this.type===i.SAMPLER_CUBE_SHADOW?r=sl(Sp):r=Ep;for(let o=0;o!==a;++o)e.setTextureCube(t[o]||r,s[o])}function F_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Fe(n,s)||(i.uniform1iv(this.addr,s),Be(n,s));for(let r=0;r!==a;++r)e.setTexture2DArray(t[r]||wp,s[r])}function B_(i){switch(i){case 5126:return y_;case 35664:return __;case 35665:return v_;case 35666:return M_;case 35674:return S_;case 35675:return w_;case 35676:return A_;case 5124:case 35670:return E_;case 35667:case 35671:return T_;case 35668:case 35672:return I_;case 35669:case 35673:return R_;case 5125:return C_;case 36294:return N_;case 36295:return P_;case 36296:return L_;case 35678:case 36198:case 36298:case 36306:case 35682:return D_;case 35679:case 36299:case 36307:return U_;case 35680:case 36300:case 36308:case 36293:return O_;case 36289:case 36303:case 36311:case 36292:return F_}}function sp(i,t){i.seq.push(t),i.map[t.id]=t}function k_(i,t,e){let n=i.name,a=n.length;for(gd.lastIndex=0;;){let s=gd.exec(n),r=gd.lastIndex,o=s[1],c=s[2]==="]",l=s[3];if(c&&(o=o|0),l===void 0||l==="["&&r+2===a){sp(e,l===void 0?new xd(o,i,t):new yd(o,i,t));break}else{let u=e.map[o];u===void 0&&(u=new _d(o),sp(e,u)),e=u}}}function rp(i,t,e){let n=i.createShader(t);return i.shaderSource(n,e),i.compileShader(n),n}function H_(i,t){let e=i.split(`
`),n=[],a=Math.max(t-6,0),s=Math.min(t+6,e.length);for(let r=a;r<s;r++){let o=r+1;n.push(`${o===t?">":" "} ${o}: ${e[r]}`)}return n.join(`
`)}function G_(i){Jt._getMatrix(op,Jt.workingColorSpace,i);let t=`mat3( ${op.elements.map(e=>e.toFixed(4))} )`;switch(Jt.getTransfer(i)){case Js:return[t,"LinearTransferOETF"];case ue:return[t,"sRGBTransferOETF"];default:return Dt("WebGLProgram: Unsupported color space: ",i),[t,"LinearTransferOETF"]}}function cp(i,t,e){let n=i.getShaderParameter(t,i.COMPILE_STATUS),s=(i.getShaderInfoLog(t)||"").trim();if(n&&s==="")return"";let r=/ERROR: 0:(\d+)/.exec(s);if(r){let o=parseInt(r[1]);return e.toUpperCase()+`

`+s+`

`+H_(i.getShaderSource(t),o)}else return s}function W_(i,t){let e=G_(t);return[`vec4 ${i}( vec4 value ) {`,`	return ${e[1]}( vec4( ${e[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}function X_(i,t){let e=j_[t];return e===void 0?(Dt("WebGLProgram: Unsupported toneMapping:",t),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+e+"ToneMapping( color ); }"}function q_(){Jt.getLuminanceCoefficients(el);let i=el.x.toFixed(4),t=el.y.toFixed(4),e=el.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${t}, ${e} );`,"	return dot( weights, rgb );","}"].join(`
`)}function Y_(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Br).join(`
`)}function J_(i){let t=[];for(let e in i){let n=i[e];n!==!1&&t.push("#define "+e+" "+n)}return t.join(`
`)}function K_(i,t){let e={},n=i.getProgramParameter(t,i.ACTIVE_ATTRIBUTES);for(let a=0;a<n;a++){let s=i.getActiveAttrib(t,a),r=s.name,o=1;s.type===i.FLOAT_MAT2&&(o=2),s.type===i.FLOAT_MAT3&&(o=3),s.type===i.FLOAT_MAT4&&(o=4),e[r]={type:s.type,location:i.getAttribLocation(t,r),locationSize:o}}return e}function Br(i){return i!==""}function lp(i,t){let e=t.numSpotLightShadows+t.numSpotLightMaps-t.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,t.numSunLights).replace(/NUM_DIR_LIGHTS/g,t.numDirLights).replace(/NUM_SPOT_LIGHTS/g,t.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,t.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,e).replace(/NUM_RECT_AREA_LIGHTS/g,t.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,t.numPointLights).replace(/NUM_HEMI_LIGHTS/g,t.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,t.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,t.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,t.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,t.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,t.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,t.numLightProbeGrids)}function hp(i,t){return i.replace(/NUM_CLIPPING_PLANES/g,t.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,t.numClippingPlanes-t.numClipIntersection)}function vd(i){return i.replace(Z_,Q_)}function Q_(i,t){let e=jt[t];if(e===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+t+">");return vd(e)}function dp(i){return i.replace($_,tv)}function tv(i,t,e,n){let a="";for(let s=parseInt(t);s<parseInt(e);s++)a+=n.replace(/\[\s*i\s*\]/g,"[ "+s+" ]").replace(/UNROLLED_LOOP_INDEX/g,s);return a}function up(i){let t=`precision ${i.precision} float;
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
#define LOW_PRECISION`),t}function nv(i){return ev[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}function av(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":iv[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}function rv(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":sv[i.combine]||"ENVMAP_BLENDING_NONE"}function ov(i,t,e,n){let a=i.getContext(),s=e.defines,r=e.vertexShader,o=e.fragmentShader,c=nv(e),l=e.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=av(e),u=rv(e),d=Y_(e),f=J_(s),b=a.createProgram(),_,m,x=e.glslVersion?"#version "+e.glslVersion+`
`:"";e.isRawShaderMaterial?(_=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f].filter(Br).join(`
`),_.length>0&&(_+=`
`),m=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f].filter(Br).join(`
`),m.length>0&&(m+=`
`)):(_=[up(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f,e.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",e.batching?"#define USE_BATCHING":"",e.batchingColor?"#define USE_BATCHING_COLOR":"",e.instancing?"#define USE_INSTANCING":"",e.instancingColor?"#define USE_INSTANCING_COLOR":"",e.instancingMorph?"#define USE_INSTANCING_MORPH":"",e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.map?"#define USE_MAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+h:"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.displacementMap?"#define USE_DISPLACEMENTMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.mapUv?"#define MAP_UV "+e.mapUv:"",e.alphaMapUv?"#define ALPHAMAP_UV "+e.alphaMapUv:"",e.lightMapUv?"#define LIGHTMAP_UV "+e.lightMapUv:"",e.aoMapUv?"#define AOMAP_UV "+e.aoMapUv:"",e.emissiveMapUv?"#define EMISSIVEMAP_UV "+e.emissiveMapUv:"",e.bumpMapUv?"#define BUMPMAP_UV "+e.bumpMapUv:"",e.normalMapUv?"#define NORMALMAP_UV "+e.normalMapUv:"",e.displacementMapUv?"#define DISPLACEMENTMAP_UV "+e.displacementMapUv:"",e.metalnessMapUv?"#define METALNESSMAP_UV "+e.metalnessMapUv:"",e.roughnessMapUv?"#define ROUGHNESSMAP_UV "+e.roughnessMapUv:"",e.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+e.anisotropyMapUv:"",e.clearcoatMapUv?"#define CLEARCOATMAP_UV "+e.clearcoatMapUv:"",e.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+e.clearcoatNormalMapUv:"",e.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+e.clearcoatRoughnessMapUv:"",e.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+e.diffuseRoughnessMapUv:"",e.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+e.iridescenceMapUv:"",e.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+e.iridescenceThicknessMapUv:"",e.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+e.sheenColorMapUv:"",e.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+e.sheenRoughnessMapUv:"",e.specularMapUv?"#define SPECULARMAP_UV "+e.specularMapUv:"",e.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+e.specularColorMapUv:"",e.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+e.specularIntensityMapUv:"",e.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+e.transmissionMapUv:"",e.thicknessMapUv?"#define THICKNESSMAP_UV "+e.thicknessMapUv:"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexNormals?"#define HAS_NORMAL":"",e.vertexColors?"#define USE_COLOR":"",e.vertexAlphas?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.flatShading?"#define FLAT_SHADED":"",e.skinning?"#define USE_SKINNING":"",e.morphTargets?"#define USE_MORPHTARGETS":"",e.morphNormals&&e.flatShading===!1?"#define USE_MORPHNORMALS":"",e.morphColors?"#define USE_MORPHCOLORS":"",e.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+e.morphTextureStride:"",e.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+e.morphTargetsCount:"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.sizeAttenuation?"#define USE_SIZEATTENUATION":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Br).join(`
`),m=[up(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f,e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",e.map?"#define USE_MAP":"",e.matcap?"#define USE_MATCAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+l:"",e.envMap?"#define "+h:"",e.envMap?"#define "+u:"",e.envMapPMREM?"#define ENVMAP_MAX_LOD "+e.envMapMaxLod+".0":"",e.envMapPMREM?"#define ENVMAP_SIZE "+e.envMapSize+".0":"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoat?"#define USE_CLEARCOAT":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.dispersion?"#define USE_DISPERSION":"",e.retroreflection?"#define USE_RETROREFLECTION":"",e.iridescence?"#define USE_IRIDESCENCE":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaTest?"#define USE_ALPHATEST":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.sheen?"#define USE_SHEEN":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexColors||e.instancingColor?"#define USE_COLOR":"",e.vertexAlphas||e.batchingColor?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.gradientMap?"#define USE_GRADIENTMAP":"",e.flatShading?"#define FLAT_SHADED":"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",e.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",e.toneMapping!==ci?"#define TONE_MAPPING":"",e.toneMapping!==ci?jt.tonemapping_pars_fragment:"",e.toneMapping!==ci?X_("toneMapping",e.toneMapping):"",e.dithering?"#define DITHERING":"",e.opaque?"#define OPAQUE":"",jt.colorspace_pars_fragment,W_("linearToOutputTexel",e.outputColorSpace),q_(),e.useDepthPacking?"#define DEPTH_PACKING "+e.depthPacking:"",`
`].filter(Br).join(`
`)),r=vd(r),r=lp(r,e),r=hp(r,e),o=vd(o),o=lp(o,e),o=hp(o,e),r=dp(r),o=dp(o),e.isRawShaderMaterial!==!0&&(x=`#version 300 es
`,_=[d,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+_,m=["#define varying in",e.glslVersion===ed?"":"layout(location = 0) out highp vec4 pc_fragColor;",e.glslVersion===ed?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+m);let v=x+_+r,w=x+m+o,p=rp(a,a.VERTEX_SHADER,v),y=rp(a,a.FRAGMENT_SHADER,w);a.attachShader(b,p),a.attachShader(b,y),e.index0AttributeName!==void 0?a.bindAttribLocation(b,0,e.index0AttributeName):e.hasPositionAttribute===!0&&a.bindAttribLocation(b,0,"position"),a.linkProgram(b);function S(A){if(i.debug.checkShaderErrors){let I=a.getProgramInfoLog(b)||"",C=a.getShaderInfoLog(p)||"",P=a.getShaderInfoLog(y)||"",N=I.trim(),U=C.trim(),z=P.trim(),F=!0,K=!0;if(a.getProgramParameter(b,a.LINK_STATUS)===!1)if(F=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(a,b,p,y);else{let H=cp(a,p,"vertex"),J=cp(a,y,"fragment");Ft("WebGLProgram: Shader Error "+a.getError()+" - VALIDATE_STATUS "+a.getProgramParameter(b,a.VALIDATE_STATUS)+`

Material Name: `+A.name+`
Material Type: `+A.type+`

Program Info Log: `+N+`
`+H+`
`+J)}else N!==""?Dt("WebGLProgram: Program Info Log:",N):(U===""||z==="")&&(K=!1);K&&(A.diagnostics={runnable:F,programLog:N,vertexShader:{log:U,prefix:_},fragmentShader:{log:z,prefix:m}})}a.deleteShader(p),a.deleteShader(y),g=new ds(a,b),M=K_(a,b)}let g;this.getUniforms=function(){return g===void 0&&S(this),g};let M;this.getAttributes=function(){return M===void 0&&S(this),M};let E=e.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return E===!1&&(E=a.getProgramParameter(b,z_)),E},this.destroy=function(){n.releaseStatesOfProgram(this),a.deleteProgram(b),this.program=void 0},this.type=e.shaderType,this.name=e.shaderName,this.id=V_++,this.cacheKey=t,this.usedTimes=1,this.program=b,this.vertexShader=p,this.fragmentShader=y,this}function lv(i){return i===li||i===Dr||i===Ur}function hv(i,t,e,n,a,s){let r=new Za,o=new Md,c=new Set,l=[],h=new Map,u=n.logarithmicDepthBuffer,d={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function f(g){return c.add(g),g===0?"uv":`uv${g}`}function b(g,M,E,A,I,C){let P=A.fog,N=I.geometry,U=g.isMeshStandardMaterial||g.isMeshLambertMaterial||g.isMeshPhongMaterial?A.environment:null,z=g.isMeshStandardMaterial||g.isMeshLambertMaterial&&!g.envMap||g.isMeshPhongMaterial&&!g.envMap,F=t.get(g.envMap||U,z),K=d[g.type],H=n.precision;g.precision!==null&&(H=n.getMaxPrecision(g.precision),H!==g.precision&&Dt("WebGLProgram.getParameters:",g.precision,"not supported, using",H,"instead."));let J=N.morphAttributes.position||N.morphAttributes.normal||N.morphAttributes.color,tt=J!==void 0?J.length:0,ft=0;N.morphAttributes.position!==void 0&&(ft=1),N.morphAttributes.normal!==void 0&&(ft=2),N.morphAttributes.color!==void 0&&(ft=3);let Ct,q,st,xt;if(K){let yt=yn[K];Ct=yt.vertexShader,q=yt.fragmentShader}else{Ct=g.vertexShader,q=g.fragmentShader;let yt=o.getVertexShaderStage(g),pe=o.getFragmentShaderStage(g);o.update(g,yt,pe),st=yt.id,xt=pe.id}let It=i.getRenderTarget(),mt=i.state.buffers.depth.getReversed(),Ot=I.isInstancedMesh===!0,Me=I.isBatchedMesh===!0,Lt=!!g.map,$t=!!g.matcap,Yt=!!F,qt=Yt&&F.isPMREMTexture===!0,De=!!g.aoMap,et=!!g.lightMap,vt=!!g.bumpMap&&g.wireframe===!1,At=!!g.normalMap,ne=!!g.displacementMap,Vt=!!g.emissiveMap,Se=!!g.metalnessMap,xe=!!g.roughnessMap,ge=g.anisotropy>0,B=g.clearcoat>0,Te=g.diffuseRoughness>0,ie=g.dispersion>0,te=g.retroreflectivity>0,lt=g.iridescence>0,de=g.sheen>0,Et=g.transmission>0,Nt=ge&&!!g.anisotropyMap,L=B&&!!g.clearcoatMap,T=B&&!!g.clearcoatNormalMap,V=B&&!!g.clearcoatRoughnessMap,at=Te&&!!g.diffuseRoughnessMap,$=lt&&!!g.iridescenceMap,rt=lt&&!!g.iridescenceThicknessMap,dt=de&&!!g.sheenColorMap,Z=de&&!!g.sheenRoughnessMap,j=!!g.specularMap,ut=!!g.specularColorMap,D=!!g.specularIntensityMap,Q=Et&&!!g.transmissionMap,Y=Et&&!!g.thicknessMap,nt=!!g.gradientMap,ot=!!g.alphaMap,ht=g.alphaTest>0,Rt=!!g.alphaHash,Wt=!!g.extensions,ct=ci;g.toneMapped&&(It===null||It.isXRRenderTarget===!0)&&(ct=i.toneMapping);let Pt=qt?F.isCompressedCubeTexture?F.image[0].mipmaps:F.mipmaps:null,Gt={shaderID:K,shaderType:g.type,shaderName:g.name,vertexShader:Ct,fragmentShader:q,defines:g.defines,customVertexShaderID:st,customFragmentShaderID:xt,isRawShaderMaterial:g.isRawShaderMaterial===!0,glslVersion:g.glslVersion,precision:H,batching:Me,batchingColor:Me&&I._colorsTexture!==null,instancing:Ot,instancingColor:Ot&&I.instanceColor!==null,instancingMorph:Ot&&I.morphTexture!==null,outputColorSpace:It===null?i.outputColorSpace:It.isXRRenderTarget===!0?It.texture.colorSpace:Jt.workingColorSpace,alphaToCoverage:!!g.alphaToCoverage,map:Lt,matcap:$t,envMap:Yt,envMapMode:Yt&&F.mapping,envMapPMREM:qt,envMapMaxLod:qt?Pt.length-1:null,envMapSize:qt?Pt[0].width:null,aoMap:De,lightMap:et,bumpMap:vt,normalMap:At,displacementMap:ne,emissiveMap:Vt,normalMapObjectSpace:At&&g.normalMapType===Of,normalMapTangentSpace:At&&g.normalMapType===Qc,packedNormalMap:At&&g.normalMapType===Qc&&lv(g.normalMap.format),metalnessMap:Se,roughnessMap:xe,anisotropy:ge,anisotropyMap:Nt,clearcoat:B,clearcoatMap:L,clearcoatNormalMap:T,clearcoatRoughnessMap:V,diffuseRoughness:Te,diffuseRoughnessMap:at,dispersion:ie,retroreflection:te,iridescence:lt,iridescenceMap:$,iridescenceThicknessMap:rt,sheen:de,sheenColorMap:dt,sheenRoughnessMap:Z,specularMap:j,specularColorMap:ut,specularIntensityMap:D,transmission:Et,transmissionMap:Q,thicknessMap:Y,gradientMap:nt,opaque:g.transparent===!1&&g.blending===rs&&g.alphaToCoverage===!1,alphaMap:ot,alphaTest:ht,alphaHash:Rt,combine:g.combine,mapUv:Lt&&f(g.map.channel),aoMapUv:De&&f(g.aoMap.channel),lightMapUv:et&&f(g.lightMap.channel),bumpMapUv:vt&&f(g.bumpMap.channel),normalMapUv:At&&f(g.normalMap.channel),displacementMapUv:ne&&f(g.displacementMap.channel),emissiveMapUv:Vt&&f(g.emissiveMap.channel),metalnessMapUv:Se&&f(g.metalnessMap.channel),roughnessMapUv:xe&&f(g.roughnessMap.channel),anisotropyMapUv:Nt&&f(g.anisotropyMap.channel),clearcoatMapUv:L&&f(g.clearcoatMap.channel),clearcoatNormalMapUv:T&&f(g.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:V&&f(g.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:at&&f(g.diffuseRoughnessMap.channel),iridescenceMapUv:$&&f(g.iridescenceMap.channel),iridescenceThicknessMapUv:rt&&f(g.iridescenceThicknessMap.channel),sheenColorMapUv:dt&&f(g.sheenColorMap.channel),sheenRoughnessMapUv:Z&&f(g.sheenRoughnessMap.channel),specularMapUv:j&&f(g.specularMap.channel),specularColorMapUv:ut&&f(g.specularColorMap.channel),specularIntensityMapUv:D&&f(g.specularIntensityMap.channel),transmissionMapUv:Q&&f(g.transmissionMap.channel),thicknessMapUv:Y&&f(g.thicknessMap.channel),alphaMapUv:ot&&f(g.alphaMap.channel),vertexTangents:!!N.attributes.tangent&&(At||ge),vertexNormals:!!N.attributes.normal,vertexColors:g.vertexColors,vertexAlphas:g.vertexColors===!0&&!!N.attributes.color&&N.attributes.color.itemSize===4,pointsUvs:I.isPoints===!0&&!!N.attributes.uv&&(Lt||ot),fog:!!P,useFog:g.fog===!0,fogExp2:!!P&&P.isFogExp2,flatShading:g.wireframe===!1&&(g.flatShading===!0||N.attributes.normal===void 0&&At===!1&&(g.isMeshLambertMaterial||g.isMeshPhongMaterial||g.isMeshStandardMaterial||g.isMeshPhysicalMaterial)),sizeAttenuation:g.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:mt,skinning:I.isSkinnedMesh===!0,hasPositionAttribute:N.attributes.position!==void 0,morphTargets:N.morphAttributes.position!==void 0,morphNormals:N.morphAttributes.normal!==void 0,morphColors:N.morphAttributes.color!==void 0,morphTargetsCount:tt,morphTextureStride:ft,numSunLights:M.sun.length,numDirLights:M.directional.length,numPointLights:M.point.length,numSpotLights:M.spot.length,numSpotLightMaps:M.spotLightMap.length,numRectAreaLights:M.rectArea.length,numHemiLights:M.hemi.length,numSunLightShadows:M.sunShadowMap.length,numDirLightShadows:M.directionalShadowMap.length,numPointLightShadows:M.pointShadowMap.length,numSpotLightShadows:M.spotShadowMap.length,numSpotLightShadowsWithMaps:M.numSpotLightShadowsWithMaps,numLightProbes:M.numLightProbes,numLightProbeGrids:C.filter(yt=>yt.texture!==null).length,numClippingPlanes:s.numPlanes,numClipIntersection:s.numIntersection,dithering:g.dithering,shadowMapEnabled:i.shadowMap.enabled&&E.length>0,shadowMapType:i.shadowMap.type,toneMapping:ct,decodeVideoTexture:Lt&&g.map.isVideoTexture===!0&&Jt.getTransfer(g.map.colorSpace)===ue,decodeVideoTextureEmissive:Vt&&g.emissiveMap.isVideoTexture===!0&&Jt.getTransfer(g.emissiveMap.colorSpace)===ue,premultipliedAlpha:g.premultipliedAlpha,doubleSided:g.side===Bn,flipSided:g.side===Xe,useDepthPacking:g.depthPacking>=0,depthPacking:g.depthPacking||0,index0AttributeName:g.index0AttributeName,extensionClipCullDistance:Wt&&g.extensions.clipCullDistance===!0&&e.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Wt&&g.extensions.multiDraw===!0||Me)&&e.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:e.has("KHR_parallel_shader_compile"),customProgramCacheKey:g.customProgramCacheKey()};return Gt.vertexUv1s=c.has(1),Gt.vertexUv2s=c.has(2),Gt.vertexUv3s=c.has(3),c.clear(),Gt}function _(g){let M=[];if(g.shaderID?M.push(g.shaderID):(M.push(g.customVertexShaderID),M.push(g.customFragmentShaderID)),g.defines!==void 0)for(let E in g.defines)M.push(E),M.push(g.defines[E]);return g.isRawShaderMaterial===!1&&(m(M,g),x(M,g),M.push(i.outputColorSpace)),M.push(g.customProgramCacheKey),M.join()}function m(g,M){g.push(M.precision),g.push(M.outputColorSpace),g.push(M.envMapMode),g.push(M.envMapPMREM),g.push(M.envMapMaxLod),g.push(M.envMapSize),g.push(M.mapUv),g.push(M.alphaMapUv),g.push(M.lightMapUv),g.push(M.aoMapUv),g.push(M.bumpMapUv),g.push(M.normalMapUv),g.push(M.displacementMapUv),g.push(M.emissiveMapUv),g.push(M.metalnessMapUv),g.push(M.roughnessMapUv),g.push(M.anisotropyMapUv),g.push(M.clearcoatMapUv),g.push(M.clearcoatNormalMapUv),g.push(M.clearcoatRoughnessMapUv),g.push(M.diffuseRoughnessMapUv),g.push(M.iridescenceMapUv),g.push(M.iridescenceThicknessMapUv),g.push(M.sheenColorMapUv),g.push(M.sheenRoughnessMapUv),g.push(M.specularMapUv),g.push(M.specularColorMapUv),g.push(M.specularIntensityMapUv),g.push(M.transmissionMapUv),g.push(M.thicknessMapUv),g.push(M.combine),g.push(M.fogExp2),g.push(M.sizeAttenuation),g.push(M.morphTargetsCount),g.push(M.numSunLights),g.push(M.numDirLights),g.push(M.numPointLights),g.push(M.numSpotLights),g.push(M.numSpotLightMaps),g.push(M.numHemiLights),g.push(M.numRectAreaLights),g.push(M.numSunLightShadows),g.push(M.numDirLightShadows),g.push(M.numPointLightShadows),g.push(M.numSpotLightShadows),g.push(M.numSpotLightShadowsWithMaps),g.push(M.numLightProbes),g.push(M.numLightProbeGrids),g.push(M.shadowMapType),g.push(M.toneMapping),g.push(M.numClippingPlanes),g.push(M.numClipIntersection),g.push(M.depthPacking)}function x(g,M){r.disableAll(),M.instancing&&r.enable(0),M.instancingColor&&r.enable(1),M.instancingMorph&&r.enable(2),M.matcap&&r.enable(3),M.envMap&&r.enable(4),M.normalMapObjectSpace&&r.enable(5),M.normalMapTangentSpace&&r.enable(6),M.clearcoat&&r.enable(7),M.iridescence&&r.enable(8),M.alphaTest&&r.enable(9),M.vertexColors&&r.enable(10),M.vertexAlphas&&r.enable(11),M.vertexUv1s&&r.enable(12),M.vertexUv2s&&r.enable(13),M.vertexUv3s&&r.enable(14),M.vertexTangents&&r.enable(15),M.anisotropy&&r.enable(16),M.alphaHash&&r.enable(17),M.batching&&r.enable(18),M.dispersion&&r.enable(19),M.retroreflection&&r.enable(24),M.diffuseRoughness&&r.enable(25),M.batchingColor&&r.enable(20),M.gradientMap&&r.enable(21),M.packedNormalMap&&r.enable(22),M.vertexNormals&&r.enable(23),g.push(r.mask),r.disableAll(),M.fog&&r.enable(0),M.useFog&&r.enable(1),M.flatShading&&r.enable(2),M.logarithmicDepthBuffer&&r.enable(3),M.reversedDepthBuffer&&r.enable(4),M.skinning&&r.enable(5),M.morphTargets&&r.enable(6),M.morphNormals&&r.enable(7),M.morphColors&&r.enable(8),M.premultipliedAlpha&&r.enable(9),M.shadowMapEnabled&&r.enable(10),M.doubleSided&&r.enable(11),M.flipSided&&r.enable(12),M.useDepthPacking&&r.enable(13),M.dithering&&r.enable(14),M.transmission&&r.enable(15),M.sheen&&r.enable(16),M.opaque&&r.enable(17),M.pointsUvs&&r.enable(18),M.decodeVideoTexture&&r.enable(19),M.decodeVideoTextureEmissive&&r.enable(20),M.alphaToCoverage&&r.enable(21),M.numLightProbeGrids>0&&r.enable(22),M.hasPositionAttribute&&r.enable(23),g.push(r.mask)}function v(g){let M=d[g.type],E;if(M){let A=yn[M];E=Or.clone(A.uniforms)}else E=g.uniforms;return E}function w(g,M){let E=h.get(M);return E!==void 0?++E.usedTimes:(E=new ov(i,M,g,a),l.push(E),h.set(M,E)),E}function p(g){if(--g.usedTimes===0){let M=l.indexOf(g);l[M]=l[l.length-1],l.pop(),h.delete(g.cacheKey),g.destroy()}}function y(g){o.remove(g)}function S(){o.dispose()}return{getParameters:b,getProgramCacheKey:_,getUniforms:v,acquireProgram:w,releaseProgram:p,releaseShaderCache:y,programs:l,dispose:S}}function dv(){let i=new WeakMap;function t(r){return i.has(r)}function e(r){let o=i.get(r);return o===void 0&&(o={},i.set(r,o)),o}function n(r){i.delete(r)}function a(r,o,c){i.get(r)[o]=c}function s(){i=new WeakMap}return{has:t,get:e,remove:n,update:a,dispose:s}}function uv(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.material.id!==t.material.id?i.material.id-t.material.id:i.materialVariant!==t.materialVariant?i.materialVariant-t.materialVariant:i.z!==t.z?i.z-t.z:i.id-t.id}function fp(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.z!==t.z?t.z-i.z:i.id-t.id}function pp(){let i=[],t=0,e=[],n=[],a=[];function s(){t=0,e.length=0,n.length=0,a.length=0}function r(d){let f=0;return d.isInstancedMesh&&(f+=2),d.isSkinnedMesh&&(f+=1),f}function o(d,f,b,_,m,x){let v=i[t];return v===void 0?(v={id:d.id,object:d,geometry:f,material:b,materialVariant:r(d),groupOrder:_,renderOrder:d.renderOrder,z:m,group:x},i[t]=v):(v.id=d.id,v.object=d,v.geometry=f,v.material=b,v.materialVariant=r(d),v.groupOrder=_,v.renderOrder=d.renderOrder,v.z=m,v.group=x),t++,v}function c(d,f,b,_,m,x,v){v.reversedDepth===!0&&(m=-m);let w=o(d,f,b,_,m,x);b.transmission>0?n.push(w):b.transparent===!0?a.push(w):e.push(w)}function l(d,f,b,_,m,x){let v=o(d,f,b,_,m,x);b.transmission>0?n.unshift(v):b.transparent===!0?a.unshift(v):e.unshift(v)}function h(d,f){e.length>1&&e.sort(d||uv),n.length>1&&n.sort(f||fp),a.length>1&&a.sort(f||fp)}function u(){for(let d=t,f=i.length;d<f;d++){let b=i[d];if(b.id===null)break;b.id=null,b.object=null,b.geometry=null,b.material=null,b.group=null}}return{opaque:e,transmissive:n,transparent:a,init:s,push:c,unshift:l,finish:u,sort:h}}function fv(){let i=new WeakMap;function t(n,a){let s=i.get(n),r;return s===void 0?(r=new pp,i.set(n,[r])):a>=s.length?(r=new pp,s.push(r)):r=s[a],r}function e(){i=new WeakMap}return{get:t,dispose:e}}function pv(){let i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={direction:new k,color:new Ht};break;case"SpotLight":e={position:new k,direction:new k,color:new Ht,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":e={position:new k,color:new Ht,distance:0,decay:0};break;case"HemisphereLight":e={direction:new k,skyColor:new Ht,groundColor:new Ht};break;case"RectAreaLight":e={color:new Ht,position:new k,halfWidth:new k,halfHeight:new k};break}return i[t.id]=e,e}}}function mv(){let i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ut};break;case"SpotLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ut};break;case"PointLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ut,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[t.id]=e,e}}}function bv(i,t){return(t.castShadow?2:0)-(i.castShadow?2:0)+(t.map?1:0)-(i.map?1:0)}function xv(i){let t=new pv,e=mv(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)n.probe.push(new k);let a=new k,s=new se,r=new se;function o(l){let h=0,u=0,d=0;for(let C=0;C<9;C++)n.probe[C].set(0,0,0);let f=0,b=0,_=0,m=0,x=0,v=0,w=0,p=0,y=0,S=0,g=0,M=0,E=0,A=0;l.sort(bv);for(let C=0,P=l.length;C<P;C++){let N=l[C],U=N.color,z=N.intensity,F=N.distance,K=null;if(N.shadow&&N.shadow.map&&(N.shadow.map.texture.format===li?K=N.shadow.map.texture:K=N.shadow.map.depthTexture||N.shadow.map.texture),N.isAmbientLight)h+=U.r*z,u+=U.g*z,d+=U.b*z;else if(N.isLightProbe){for(let H=0;H<9;H++)n.probe[H].addScaledVector(N.sh.coefficients[H],z);A++}else if(N.isSunLight){let H=t.get(N);if(H.color.copy(N.color).multiplyScalar(N.intensity),N.castShadow){let J=N.shadow,tt=e.get(N);tt.shadowIntensity=J.intensity,tt.shadowBias=J.bias,tt.shadowNormalBias=J.normalBias,tt.shadowRadius=J.radius,tt.shadowMapSize.copy(J.mapSize).multiply(J.getFrameExtents()),n.sunShadow[b]=tt,n.sunShadowMap[b]=K;let ft=J.getViewportCount();for(let Ct=0;Ct<ft;Ct++)n.sunShadowMatrix[_+Ct]=J.getMatrix(Ct),n.sunShadowCascade[_+Ct]=J._cascadeData[Ct];_+=ft,b++}n.sun[f]=H,f++}else if(N.isDirectionalLight){let H=t.get(N);if(H.color.copy(N.color).multiplyScalar(N.intensity),N.castShadow){let J=N.shadow,tt=e.get(N);tt.shadowIntensity=J.intensity,tt.shadowBias=J.bias,tt.shadowNormalBias=J.normalBias,tt.shadowRadius=J.radius,tt.shadowMapSize=J.mapSize,n.directionalShadow[m]=tt,n.directionalShadowMap[m]=K,n.directionalShadowMatrix[m]=N.shadow.matrix,y++}n.directional[m]=H,m++}else if(N.isSpotLight){let H=t.get(N);H.position.setFromMatrixPosition(N.matrixWorld),H.color.copy(U).multiplyScalar(z),H.distance=F,H.coneCos=Math.cos(N.angle),H.penumbraCos=Math.cos(N.angle*(1-N.penumbra)),H.decay=N.decay,n.spot[v]=H;let J=N.shadow;if(N.map&&(n.spotLightMap[M]=N.map,M++,J.updateMatrices(N),N.castShadow&&E++),n.spotLightMatrix[v]=J.matrix,N.castShadow){let tt=e.get(N);tt.shadowIntensity=J.intensity,tt.shadowBias=J.bias,tt.shadowNormalBias=J.normalBias,tt.shadowRadius=J.radius,tt.shadowMapSize=J.mapSize,n.spotShadow[v]=tt,n.spotShadowMap[v]=K,g++}v++}else if(N.isRectAreaLight){let H=t.get(N);H.color.copy(U).multiplyScalar(z),H.halfWidth.set(N.width*.5,0,0),H.halfHeight.set(0,N.height*.5,0),n.rectArea[w]=H,w++}else if(N.isPointLight){let H=t.get(N);if(H.color.copy(N.color).multiplyScalar(N.intensity),H.distance=N.distance,H.decay=N.decay,N.castShadow){let J=N.shadow,tt=e.get(N);tt.shadowIntensity=J.intensity,tt.shadowBias=J.bias,tt.shadowNormalBias=J.normalBias,tt.shadowRadius=J.radius,tt.shadowMapSize=J.mapSize,tt.shadowCameraNear=J.camera.near,tt.shadowCameraFar=J.camera.far,n.pointShadow[x]=tt,n.pointShadowMap[x]=K,n.pointShadowMatrix[x]=N.shadow.matrix,S++}n.point[x]=H,x++}else if(N.isHemisphereLight){let H=t.get(N);H.skyColor.copy(N.color).multiplyScalar(z),H.groundColor.copy(N.groundColor).multiplyScalar(z),n.hemi[p]=H,p++}}w>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=bt.LTC_FLOAT_1,n.rectAreaLTC2=bt.LTC_FLOAT_2):(n.rectAreaLTC1=bt.LTC_HALF_1,n.rectAreaLTC2=bt.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=u,n.ambient[2]=d;let I=n.hash;(I.sunLength!==f||I.directionalLength!==m||I.pointLength!==x||I.spotLength!==v||I.rectAreaLength!==w||I.hemiLength!==p||I.numSunShadows!==b||I.numDirectionalShadows!==y||I.numPointShadows!==S||I.numSpotShadows!==g||I.numSpotMaps!==M||I.numLightProbes!==A)&&(n.sun.length=f,n.directional.length=m,n.spot.length=v,n.rectArea.length=w,n.point.length=x,n.hemi.length=p,n.sunShadow.length=b,n.sunShadowMap.length=b,n.sunShadowMatrix.length=_,n.sunShadowCascade.length=_,n.directionalShadow.length=y,n.directionalShadowMap.length=y,n.directionalShadowMatrix.length=y,n.pointShadow.length=S,n.pointShadowMap.length=S,n.pointShadowMatrix.length=S,n.spotShadow.length=g,n.spotShadowMap.length=g,n.spotLightMatrix.length=g+M-E,n.spotLightMap.length=M,n.numSpotLightShadowsWithMaps=E,n.numLightProbes=A,I.sunLength=f,I.directionalLength=m,I.pointLength=x,I.spotLength=v,I.rectAreaLength=w,I.hemiLength=p,I.numSunShadows=b,I.numDirectionalShadows=y,I.numPointShadows=S,I.numSpotShadows=g,I.numSpotMaps=M,I.numLightProbes=A,n.version=gv++)}function c(l,h){let u=0,d=0,f=0,b=0,_=0,m=0,x=h.matrixWorldInverse;for(let v=0,w=l.length;v<w;v++){let p=l[v];if(p.isSunLight){let y=n.sun[u];y.direction.setFromMatrixPosition(p.matrixWorld),y.direction.transformDirection(x),u++}else if(p.isDirectionalLight){let y=n.directional[d];y.direction.setFromMatrixPosition(p.matrixWorld),a.setFromMatrixPosition(p.target.matrixWorld),y.direction.sub(a),y.direction.transformDirection(x),d++}else if(p.isSpotLight){let y=n.spot[b];y.position.setFromMatrixPosition(p.matrixWorld),y.position.applyMatrix4(x),y.direction.setFromMatrixPosition(p.matrixWorld),a.setFromMatrixPosition(p.target.matrixWorld),y.direction.sub(a),y.direction.transformDirection(x),b++}else if(p.isRectAreaLight){let y=n.rectArea[_];y.position.setFromMatrixPosition(p.matrixWorld),y.position.applyMatrix4(x),r.identity(),s.copy(p.matrixWorld),s.premultiply(x),r.extractRotation(s),y.halfWidth.set(p.width*.5,0,0),y.halfHeight.set(0,p.height*.5,0),y.halfWidth.applyMatrix4(r),y.halfHeight.applyMatrix4(r),_++}else if(p.isPointLight){let y=n.point[f];y.position.setFromMatrixPosition(p.matrixWorld),y.position.applyMatrix4(x),f++}else if(p.isHemisphereLight){let y=n.hemi[m];y.direction.setFromMatrixPosition(p.matrixWorld),y.direction.transformDirection(x),m++}}}return{setup:o,setupView:c,state:n}}function mp(i){let t=new xv(i),e=[],n=[],a=[];function s(u){h.camera=u,e.length=0,n.length=0,a.length=0}function r(u){u.isLightProbeGrid?a.push(u):e.push(u)}function o(u){n.push(u)}function c(){t.setup(e),a.sort((u,d)=>u.priority-d.priority||u.id-d.id)}function l(u){t.setupView(e,u)}let h={lightsArray:e,shadowsArray:n,lightProbeGridArray:a,camera:null,lights:t,transmissionRenderTarget:{},textureUnits:0};return{init:s,state:h,setupLights:c,setupLightsView:l,pushLight:r,pushShadow:o}}function yv(i){let t=new WeakMap;function e(a,s=0){let r=t.get(a),o;return r===void 0?(o=new mp(i),t.set(a,[o])):s>=r.length?(o=new mp(i),r.push(o)):o=r[s],o}function n(){t=new WeakMap}return{get:e,dispose:n}}function wv(i,t,e){let n=new Ii,a=new Ut,s=new Ut,r=new re,o=new tc,c=new ec,l={},h=e.maxTextureSize,u={[oi]:Xe,[Xe]:oi,[Bn]:Bn},d=new Fn({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Ut},radius:{value:4}},vertexShader:_v,fragmentShader:vv}),f=d.clone();f.defines.HORIZONTAL_PASS=1;let b=new Le;b.setAttribute("position",new mn(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let _=new an(b,d),m=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Ar;let x=this.type;this.render=function(S,g,M){if(m.enabled===!1||m.autoUpdate===!1&&m.needsUpdate===!1||S.length===0)return;this.type===ff&&(Dt("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Ar);let E=i.getRenderTarget(),A=i.getActiveCubeFace(),I=i.getActiveMipmapLevel(),C=i.state;C.setBlending(ba),C.buffers.depth.getReversed()===!0?C.buffers.color.setClear(0,0,0,0):C.buffers.color.setClear(1,1,1,1),C.buffers.depth.setTest(!0),C.setScissorTest(!1);let P=x!==this.type;P&&g.traverse(function(N){N.material&&(Array.isArray(N.material)?N.material.forEach(U=>U.needsUpdate=!0):N.material.needsUpdate=!0)});for(let N=0,U=S.length;N<U;N++){let z=S[N],F=z.shadow;if(F===void 0){Dt("WebGLShadowMap:",z,"has no shadow.");continue}if(F.autoUpdate===!1&&F.needsUpdate===!1)continue;a.copy(F.mapSize);let K=F.getFrameExtents();a.multiply(K),s.copy(F.mapSize),(a.x>h||a.y>h)&&(a.x>h&&(s.x=Math.floor(h/K.x),a.x=s.x*K.x,F.mapSize.x=s.x),a.y>h&&(s.y=Math.floor(h/K.y),a.y=s.y*K.y,F.mapSize.y=s.y));let H=i.state.buffers.depth.getReversed();if(F.camera._reversedDepth=H,F.map===null||P===!0){if(F.map!==null&&(F.map.depthTexture!==null&&(F.map.depthTexture.dispose(),F.map.depthTexture=null),F.map.dispose()),this.type===ss){if(z.isPointLight){Dt("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}F.map=new Cn(a.x,a.y,{format:li,type:Kn,minFilter:gn,magFilter:gn,generateMipmaps:!1}),F.map.texture.name=z.name+".shadowMap",F.map.depthTexture=new Ri(a.x,a.y,bn),F.map.depthTexture.name=z.name+".shadowMapDepth",F.map.depthTexture.format=Ei,F.map.depthTexture.compareFunction=null,F.map.depthTexture.minFilter=Pe,F.map.depthTexture.magFilter=Pe}else z.isPointLight?(F.map=new kr(a.x),F.map.depthTexture=new or(a.x,wn)):(F.map=new Cn(a.x,a.y),F.map.depthTexture=new Ri(a.x,a.y,wn)),F.map.depthTexture.name=z.name+".shadowMap",F.map.depthTexture.format=Ei,this.type===Ar?(F.map.depthTexture.compareFunction=H?Qh:Zh,F.map.depthTexture.minFilter=gn,F.map.depthTexture.magFilter=gn):(F.map.depthTexture.compareFunction=null,F.map.depthTexture.minFilter=Pe,F.map.depthTexture.magFilter=Pe);F.camera.updateProjectionMatrix()}F.map.isWebGLCubeRenderTarget!==!0&&(F.map.width!==a.x||F.map.height!==a.y)&&F.map.setSize(a.x,a.y);let J=F.map.isWebGLCubeRenderTarget?6:F.getViewportCount();z.isPointLight!==!0&&F.updateMatrices(z,M);let tt=(F.camera.layers.mask&4294967294)!==0?F.camera.layers:M.layers;for(let ft=0;ft<J;ft++){let Ct=F.getCamera(ft);if(z.isPointLight){let q=F.camera,st=F.matrix,xt=z.distance||q.far;xt!==q.far&&(q.far=xt,q.updateProjectionMatrix()),Fr.setFromMatrixPosition(z.matrixWorld),q.position.copy(Fr),bd.copy(q.position),bd.add(Mv[ft]),q.up.copy(Sv[ft]),q.lookAt(bd),q.updateMatrixWorld(),st.makeTranslation(-Fr.x,-Fr.y,-Fr.z),gp.multiplyMatrices(q.projectionMatrix,q.matrixWorldInverse),F._frustum.setFromProjectionMatrix(gp,q.coordinateSystem,q.reversedDepth)}if(F.map.isWebGLCubeRenderTarget)i.setRenderTarget(F.map,ft),i.clear();else{ft===0&&(i.setRenderTarget(F.map),i.clear());let q=F.getViewport(ft);r.set(s.x*q.x,s.y*q.y,s.x*q.z,s.y*q.w),C.viewport(r)}n=F.getFrustum(ft),p(g,M,Ct,z,tt,this.type)}F.isPointLightShadow!==!0&&this.type===ss&&v(F,M),F.needsUpdate=!1}x=this.type,m.needsUpdate=!1,i.setRenderTarget(E,A,I)};function v(S,g){let M=t.update(_);d.defines.VSM_SAMPLES!==S.blurSamples&&(d.defines.VSM_SAMPLES=S.blurSamples,f.defines.VSM_SAMPLES=S.blurSamples,d.needsUpdate=!0,f.needsUpdate=!0),S.mapPass===null?S.mapPass=new Cn(a.x,a.y,{format:li,type:Kn}):(S.mapPass.width!==S.map.width||S.mapPass.height!==S.map.height)&&S.mapPass.setSize(S.map.width,S.map.height),d.uniforms.shadow_pass.value=S.map.depthTexture,d.uniforms.resolution.value.set(S.map.width,S.map.height),d.uniforms.radius.value=S.radius,i.setRenderTarget(S.mapPass),i.clear(),i.renderBufferDirect(g,null,M,d,_,null),f.uniforms.shadow_pass.value=S.mapPass.texture,f.uniforms.resolution.value.set(S.map.width,S.map.height),f.uniforms.radius.value=S.radius,i.setRenderTarget(S.map),i.clear(),i.renderBufferDirect(g,null,M,f,_,null)}function w(S,g,M,E){let A=null,I=M.isPointLight===!0?S.customDistanceMaterial:S.customDepthMaterial;if(I!==void 0)A=I;else if(A=M.isPointLight===!0?c:o,i.localClippingEnabled&&g.clipShadows===!0&&Array.isArray(g.clippingPlanes)&&g.clippingPlanes.length!==0||g.displacementMap&&g.displacementScale!==0||g.alphaMap&&g.alphaTest>0||g.map&&g.alphaTest>0||g.alphaToCoverage===!0){let C=A.uuid,P=g.uuid,N=l[C];N===void 0&&(N={},l[C]=N);let U=N[P];U===void 0&&(U=A.clone(),N[P]=U,g.addEventListener("dispose",y)),A=U}if(A.visible=g.visible,A.wireframe=g.wireframe,E===ss?A.side=g.shadowSide!==null?g.shadowSide:g.side:A.side=g.shadowSide!==null?g.shadowSide:u[g.side],A.alphaMap=g.alphaMap,A.alphaTest=g.alphaToCoverage===!0?.5:g.alphaTest,A.map=g.map,A.clipShadows=g.clipShadows,A.clippingPlanes=g.clippingPlanes,A.clipIntersection=g.clipIntersection,A.displacementMap=g.displacementMap,A.displacementScale=g.displacementScale,A.displacementBias=g.displacementBias,A.wireframeLinewidth=g.wireframeLinewidth,A.linewidth=g.linewidth,M.isPointLight===!0&&A.isMeshDistanceMaterial===!0){let C=i.properties.get(A);C.light=M}return A}function p(S,g,M,E,A,I){if(S.visible===!1)return;if(S.layers.test(A)&&(S.isMesh||S.isLine||S.isPoints)&&(S.castShadow||S.receiveShadow&&I===ss)&&(!S.frustumCulled||S.intersectsFrustum(n))){S.modelViewMatrix.multiplyMatrices(M.matrixWorldInverse,S.matrixWorld);let N=t.update(S),U=S.material;if(Array.isArray(U)){let z=N.groups;for(let F=0,K=z.length;F<K;F++){let H=z[F],J=U[H.materialIndex];if(J&&J.visible){let tt=w(S,J,E,I);S.onBeforeShadow(i,S,g,M,N,tt,H),i.renderBufferDirect(M,null,N,tt,S,H),S.onAfterShadow(i,S,g,M,N,tt,H)}}}else if(U.visible){let z=w(S,U,E,I);S.onBeforeShadow(i,S,g,M,N,z,null),i.renderBufferDirect(M,null,N,z,S,null),S.onAfterShadow(i,S,g,M,N,z,null)}}let P=S.children;for(let N=0,U=P.length;N<U;N++)p(P[N],g,M,E,A,I)}function y(S){S.target.removeEventListener("dispose",y);for(let M in l){let E=l[M],A=S.target.uuid;A in E&&(E[A].dispose(),delete E[A])}}}function Av(i,t){function e(){let D=!1,Q=new re,Y=null,nt=new re(0,0,0,0);return{setMask:function(ot){Y!==ot&&!D&&(i.colorMask(ot,ot,ot,ot),Y=ot)},setLocked:function(ot){D=ot},setClear:function(ot,ht,Rt,Wt,ct){ct===!0&&(ot*=Wt,ht*=Wt,Rt*=Wt),Q.set(ot,ht,Rt,Wt),nt.equals(Q)===!1&&(i.clearColor(ot,ht,Rt,Wt),nt.copy(Q))},reset:function(){D=!1,Y=null,nt.set(-1,0,0,0)}}}function n(){let D=!1,Q=!1,Y=null,nt=null,ot=null;return{setReversed:function(ht){if(Q!==ht){let Rt=t.get("EXT_clip_control");ht?Rt.clipControlEXT(Rt.LOWER_LEFT_EXT,Rt.ZERO_TO_ONE_EXT):Rt.clipControlEXT(Rt.LOWER_LEFT_EXT,Rt.NEGATIVE_ONE_TO_ONE_EXT),Q=ht;let Wt=ot;ot=null,this.setClear(Wt)}},getReversed:function(){return Q},setTest:function(ht){ht?mt(i.DEPTH_TEST):Ot(i.DEPTH_TEST)},setMask:function(ht){Y!==ht&&!D&&(i.depthMask(ht),Y=ht)},setFunc:function(ht){if(Q&&(ht=Xf[ht]),nt!==ht){switch(ht){case Oo:i.depthFunc(i.NEVER);break;case Fo:i.depthFunc(i.ALWAYS);break;case Bo:i.depthFunc(i.LESS);break;case Xa:i.depthFunc(i.LEQUAL);break;case ko:i.depthFunc(i.EQUAL);break;case zo:i.depthFunc(i.GEQUAL);break;case Vo:i.depthFunc(i.GREATER);break;case Ho:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}nt=ht}},setLocked:function(ht){D=ht},setClear:function(ht){ot!==ht&&(ot=ht,Q&&(ht=1-ht),i.clearDepth(ht))},reset:function(){D=!1,Y=null,nt=null,ot=null,Q=!1}}}function a(){let D=!1,Q=null,Y=null,nt=null,ot=null,ht=null,Rt=null,Wt=null,ct=null;return{setTest:function(Pt){D||(Pt?mt(i.STENCIL_TEST):Ot(i.STENCIL_TEST))},setMask:function(Pt){Q!==Pt&&!D&&(i.stencilMask(Pt),Q=Pt)},setFunc:function(Pt,Gt,yt){(Y!==Pt||nt!==Gt||ot!==yt)&&(i.stencilFunc(Pt,Gt,yt),Y=Pt,nt=Gt,ot=yt)},setOp:function(Pt,Gt,yt){(ht!==Pt||Rt!==Gt||Wt!==yt)&&(i.stencilOp(Pt,Gt,yt),ht=Pt,Rt=Gt,Wt=yt)},setLocked:function(Pt){D=Pt},setClear:function(Pt){ct!==Pt&&(i.clearStencil(Pt),ct=Pt)},reset:function(){D=!1,Q=null,Y=null,nt=null,ot=null,ht=null,Rt=null,Wt=null,ct=null}}}let s=new e,r=new n,o=new a,c={},l=new WeakMap,h={},u={},d={},f=new WeakMap,b=[],_=null,m=!1,x=null,v=null,w=null,p=null,y=null,S=null,g=null,M=new Ht(0,0,0),E=0,A=!1,I=null,C=null,P=null,N=null,U=null,z=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS),F=!1,K=0,H=i.getParameter(i.VERSION);H.indexOf("WebGL")!==-1?(K=parseFloat(/^WebGL (\d)/.exec(H)[1]),F=K>=1):H.indexOf("OpenGL ES")!==-1&&(K=parseFloat(/^OpenGL ES (\d)/.exec(H)[1]),F=K>=2);let J=null,tt={},ft=i.getParameter(i.SCISSOR_BOX),Ct=i.getParameter(i.VIEWPORT),q=new re().fromArray(ft),st=new re().fromArray(Ct);function xt(D,Q,Y,nt){let ot=new Uint8Array(4),ht=i.createTexture();i.bindTexture(D,ht),i.texParameteri(D,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(D,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let Rt=0;Rt<Y;Rt++)D===i.TEXTURE_3D||D===i.TEXTURE_2D_ARRAY?i.texImage3D(Q,0,i.RGBA,1,1,nt,0,i.RGBA,i.UNSIGNED_BYTE,ot):i.texImage2D(Q+Rt,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,ot);return ht}let It={};It[i.TEXTURE_2D]=xt(i.TEXTURE_2D,i.TEXTURE_2D,1),It[i.TEXTURE_CUBE_MAP]=xt(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),It[i.TEXTURE_2D_ARRAY]=xt(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),It[i.TEXTURE_3D]=xt(i.TEXTURE_3D,i.TEXTURE_3D,1,1),s.setClear(0,0,0,1),r.setClear(1),o.setClear(0),mt(i.DEPTH_TEST),r.setFunc(Xa),vt(!1),At(Lh),mt(i.CULL_FACE),De(ba);function mt(D){h[D]!==!0&&(i.enable(D),h[D]=!0)}function Ot(D){h[D]!==!1&&(i.disable(D),h[D]=!1)}function Me(D,Q){return d[D]!==Q?(i.bindFramebuffer(D,Q),d[D]=Q,D===i.DRAW_FRAMEBUFFER&&(d[i.FRAMEBUFFER]=Q),D===i.FRAMEBUFFER&&(d[i.DRAW_FRAMEBUFFER]=Q),!0):!1}function Lt(D,Q){let Y=b,nt=!1;if(D){Y=f.get(Q),Y===void 0&&(Y=[],f.set(Q,Y));let ot=D.textures;if(Y.length!==ot.length||Y[0]!==i.COLOR_ATTACHMENT0){for(let ht=0,Rt=ot.length;ht<Rt;ht++)Y[ht]=i.COLOR_ATTACHMENT0+ht;Y.length=ot.length,nt=!0}}else Y[0]!==i.BACK&&(Y[0]=i.BACK,nt=!0);nt&&i.drawBuffers(Y)}function $t(D){return _!==D?(i.useProgram(D),_=D,!0):!1}let Yt={[xa]:i.FUNC_ADD,[mf]:i.FUNC_SUBTRACT,[gf]:i.FUNC_REVERSE_SUBTRACT};Yt[bf]=i.MIN,Yt[xf]=i.MAX;let qt={[yf]:i.ZERO,[_f]:i.ONE,[vf]:i.SRC_COLOR,[Fh]:i.SRC_ALPHA,[Tf]:i.SRC_ALPHA_SATURATE,[Af]:i.DST_COLOR,[Sf]:i.DST_ALPHA,[Mf]:i.ONE_MINUS_SRC_COLOR,[Bh]:i.ONE_MINUS_SRC_ALPHA,[Ef]:i.ONE_MINUS_DST_COLOR,[wf]:i.ONE_MINUS_DST_ALPHA,[If]:i.CONSTANT_COLOR,[Rf]:i.ONE_MINUS_CONSTANT_COLOR,[Cf]:i.CONSTANT_ALPHA,[Nf]:i.ONE_MINUS_CONSTANT_ALPHA};function De(D,Q,Y,nt,ot,ht,Rt,Wt,ct,Pt){if(D===ba){m===!0&&(Ot(i.BLEND),m=!1);return}if(m===!1&&(mt(i.BLEND),m=!0),D!==pf){if(D!==x||Pt!==A){if((v!==xa||y!==xa)&&(i.blendEquation(i.FUNC_ADD),v=xa,y=xa),Pt)switch(D){case rs:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Dh:i.blendFunc(i.ONE,i.ONE);break;case Uh:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case Oh:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:Ft("WebGLState: Invalid blending: ",D);break}else switch(D){case rs:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Dh:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case Uh:Ft("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Oh:Ft("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:Ft("WebGLState: Invalid blending: ",D);break}w=null,p=null,S=null,g=null,M.set(0,0,0),E=0,x=D,A=Pt}return}ot=ot||Q,ht=ht||Y,Rt=Rt||nt,(Q!==v||ot!==y)&&(i.blendEquationSeparate(Yt[Q],Yt[ot]),v=Q,y=ot),(Y!==w||nt!==p||ht!==S||Rt!==g)&&(i.blendFuncSeparate(qt[Y],qt[nt],qt[ht],qt[Rt]),w=Y,p=nt,S=ht,g=Rt),(Wt.equals(M)===!1||ct!==E)&&(i.blendColor(Wt.r,Wt.g,Wt.b,ct),M.copy(Wt),E=ct),x=D,A=!1}function et(D,Q){D.side===Bn?Ot(i.CULL_FACE):mt(i.CULL_FACE);let Y=D.side===Xe;Q&&(Y=!Y),vt(Y),D.blending===rs&&D.transparent===!1?De(ba):De(D.blending,D.blendEquation,D.blendSrc,D.blendDst,D.blendEquationAlpha,D.blendSrcAlpha,D.blendDstAlpha,D.blendColor,D.blendAlpha,D.premultipliedAlpha),r.setFunc(D.depthFunc),r.setTest(D.depthTest),r.setMask(D.depthWrite),s.setMask(D.colorWrite);let nt=D.stencilWrite;o.setTest(nt),nt&&(o.setMask(D.stencilWriteMask),o.setFunc(D.stencilFunc,D.stencilRef,D.stencilFuncMask),o.setOp(D.stencilFail,D.stencilZFail,D.stencilZPass)),Vt(D.polygonOffset,D.polygonOffsetFactor,D.polygonOffsetUnits),D.alphaToCoverage===!0?mt(i.SAMPLE_ALPHA_TO_COVERAGE):Ot(i.SAMPLE_ALPHA_TO_COVERAGE)}function vt(D){I!==D&&(D?i.frontFace(i.CW):i.frontFace(i.CCW),I=D)}function At(D){D!==df?(mt(i.CULL_FACE),D!==C&&(D===Lh?i.cullFace(i.BACK):D===uf?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):Ot(i.CULL_FACE),C=D}function ne(D){D!==P&&(F&&i.lineWidth(D),P=D)}function Vt(D,Q,Y){D?(mt(i.POLYGON_OFFSET_FILL),(N!==Q||U!==Y)&&(N=Q,U=Y,r.getReversed()&&(Q=-Q,Y=-Y),i.polygonOffset(Q,Y))):Ot(i.POLYGON_OFFSET_FILL)}function Se(D){D?mt(i.SCISSOR_TEST):Ot(i.SCISSOR_TEST)}function xe(D){D===void 0&&(D=i.TEXTURE0+z-1),J!==D&&(i.activeTexture(D),J=D)}function ge(D,Q,Y){Y===void 0&&(J===null?Y=i.TEXTURE0+z-1:Y=J);let nt=tt[Y];nt===void 0&&(nt={type:void 0,texture:void 0},tt[Y]=nt),(nt.type!==D||nt.texture!==Q)&&(J!==Y&&(i.activeTexture(Y),J=Y),i.bindTexture(D,Q||It[D]),nt.type=D,nt.texture=Q)}function B(){let D=tt[J];D!==void 0&&D.type!==void 0&&(i.bindTexture(D.type,null),D.type=void 0,D.texture=void 0)}function Te(){try{i.compressedTexImage2D(...arguments)}catch(D){Ft("WebGLState:",D)}}function ie(){try{i.compressedTexImage3D(...arguments)}catch(D){Ft("WebGLState:",D)}}function te(){try{i.texSubImage2D(...arguments)}catch(D){Ft("WebGLState:",D)}}function lt(){try{i.texSubImage3D(...arguments)}catch(D){Ft("WebGLState:",D)}}function de(){try{i.compressedTexSubImage2D(...arguments)}catch(D){Ft("WebGLState:",D)}}function Et(){try{i.compressedTexSubImage3D(...arguments)}catch(D){Ft("WebGLState:",D)}}function Nt(){try{i.texStorage2D(...arguments)}catch(D){Ft("WebGLState:",D)}}function L(){try{i.texStorage3D(...arguments)}catch(D){Ft("WebGLState:",D)}}function T(){try{i.texImage2D(...arguments)}catch(D){Ft("WebGLState:",D)}}function V(){try{i.texImage3D(...arguments)}catch(D){Ft("WebGLState:",D)}}function at(D){return u[D]!==void 0?u[D]:i.getParameter(D)}function $(D,Q){u[D]!==Q&&(i.pixelStorei(D,Q),u[D]=Q)}function rt(D){q.equals(D)===!1&&(i.scissor(D.x,D.y,D.z,D.w),q.copy(D))}function dt(D){st.equals(D)===!1&&(i.viewport(D.x,D.y,D.z,D.w),st.copy(D))}function Z(D,Q){let Y=l.get(Q);Y===void 0&&(Y=new WeakMap,l.set(Q,Y));let nt=Y.get(D);nt===void 0&&(nt=i.getUniformBlockIndex(Q,D.name),i.uniformBlockBinding(Q,nt,nt),Y.set(D,nt))}function j(D,Q,Y){let ot=l.get(Q).get(D);c[ot]!==Y&&(i.bindBufferBase(i.UNIFORM_BUFFER,ot,Y),c[ot]=Y)}function ut(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),r.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},u={},J=null,tt={},d={},c={},f=new WeakMap,b=[],_=null,m=!1,x=null,v=null,w=null,p=null,y=null,S=null,g=null,M=new Ht(0,0,0),E=0,A=!1,I=null,C=null,P=null,N=null,U=null,q.set(0,0,i.canvas.width,i.canvas.height),st.set(0,0,i.canvas.width,i.canvas.height),s.reset(),r.reset(),o.reset()}return{buffers:{color:s,depth:r,stencil:o},enable:mt,disable:Ot,bindFramebuffer:Me,drawBuffers:Lt,useProgram:$t,setBlending:De,setMaterial:et,setFlipSided:vt,setCullFace:At,setLineWidth:ne,setPolygonOffset:Vt,setScissorTest:Se,activeTexture:xe,bindTexture:ge,unbindTexture:B,compressedTexImage2D:Te,compressedTexImage3D:ie,texImage2D:T,texImage3D:V,pixelStorei:$,getParameter:at,updateUBOMapping:Z,uniformBlockBinding:j,texStorage2D:Nt,texStorage3D:L,texSubImage2D:te,texSubImage3D:lt,compressedTexSubImage2D:de,compressedTexSubImage3D:Et,scissor:rt,viewport:dt,reset:ut}}function Ev(i,t,e,n,a,s,r){let o=t.has("WEBGL_multisampled_render_to_texture")?t.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new Ut,h=new WeakMap,u=new Set,d,f=new WeakMap,b=new Set,_=new FinalizationRegistry(L=>b.delete(L)),m=!1;try{m=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function x(L,T){return m?new OffscreenCanvas(L,T):Ks("canvas")}function v(L,T,V){let at=1,$=Nt(L);if(($.width>V||$.height>V)&&(at=V/Math.max($.width,$.height)),at<1)if(typeof HTMLImageElement<"u"&&L instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&L instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&L instanceof ImageBitmap||typeof VideoFrame<"u"&&L instanceof VideoFrame){let rt=Math.floor(at*$.width),dt=Math.floor(at*$.height);d===void 0&&(d=x(rt,dt));let Z=T?x(rt,dt):d;return Z.width=rt,Z.height=dt,Z.getContext("2d").drawImage(L,0,0,rt,dt),Dt("WebGLRenderer: Texture has been resized from ("+$.width+"x"+$.height+") to ("+rt+"x"+dt+")."),Z}else return"data"in L&&Dt("WebGLRenderer: Image in DataTexture is too big ("+$.width+"x"+$.height+")."),L;return L}function w(L){return L.generateMipmaps}function p(L){i.generateMipmap(L)}function y(L){return L.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:L.isWebGL3DRenderTarget?i.TEXTURE_3D:L.isWebGLArrayRenderTarget||L.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function S(L,T,V,at,$,rt=!1){if(L!==null){if(i[L]!==void 0)return i[L];Dt("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+L+"'")}let dt;at&&(dt=t.get("EXT_texture_norm16"),dt||Dt("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let Z=T;if(T===i.RED&&(V===i.FLOAT&&(Z=i.R32F),V===i.HALF_FLOAT&&(Z=i.R16F),V===i.UNSIGNED_BYTE&&(Z=i.R8),V===i.UNSIGNED_SHORT&&dt&&(Z=dt.R16_EXT),V===i.SHORT&&dt&&(Z=dt.R16_SNORM_EXT)),T===i.RED_INTEGER&&(V===i.UNSIGNED_BYTE&&(Z=i.R8UI),V===i.UNSIGNED_SHORT&&(Z=i.R16UI),V===i.UNSIGNED_INT&&(Z=i.R32UI),V===i.BYTE&&(Z=i.R8I),V===i.SHORT&&(Z=i.R16I),V===i.INT&&(Z=i.R32I)),T===i.RG&&(V===i.FLOAT&&(Z=i.RG32F),V===i.HALF_FLOAT&&(Z=i.RG16F),V===i.UNSIGNED_BYTE&&(Z=i.RG8),V===i.UNSIGNED_SHORT&&dt&&(Z=dt.RG16_EXT),V===i.SHORT&&dt&&(Z=dt.RG16_SNORM_EXT)),T===i.RG_INTEGER&&(V===i.UNSIGNED_BYTE&&(Z=i.RG8UI),V===i.UNSIGNED_SHORT&&(Z=i.RG16UI),V===i.UNSIGNED_INT&&(Z=i.RG32UI),V===i.BYTE&&(Z=i.RG8I),V===i.SHORT&&(Z=i.RG16I),V===i.INT&&(Z=i.RG32I)),T===i.RGB_INTEGER&&(V===i.UNSIGNED_BYTE&&(Z=i.RGB8UI),V===i.UNSIGNED_SHORT&&(Z=i.RGB16UI),V===i.UNSIGNED_INT&&(Z=i.RGB32UI),V===i.BYTE&&(Z=i.RGB8I),V===i.SHORT&&(Z=i.RGB16I),V===i.INT&&(Z=i.RGB32I)),T===i.RGBA_INTEGER&&(V===i.UNSIGNED_BYTE&&(Z=i.RGBA8UI),V===i.UNSIGNED_SHORT&&(Z=i.RGBA16UI),V===i.UNSIGNED_INT&&(Z=i.RGBA32UI),V===i.BYTE&&(Z=i.RGBA8I),V===i.SHORT&&(Z=i.RGBA16I),V===i.INT&&(Z=i.RGBA32I)),T===i.RGB&&(V===i.UNSIGNED_SHORT&&dt&&(Z=dt.RGB16_EXT),V===i.SHORT&&dt&&(Z=dt.RGB16_SNORM_EXT),V===i.UNSIGNED_INT_5_9_9_9_REV&&(Z=i.RGB9_E5),V===i.UNSIGNED_INT_10F_11F_11F_REV&&(Z=i.R11F_G11F_B10F)),T===i.RGBA){let j=rt?Js:Jt.getTransfer($);V===i.FLOAT&&(Z=i.RGBA32F),V===i.HALF_FLOAT&&(Z=i.RGBA16F),V===i.UNSIGNED_BYTE&&(Z=j===ue?i.SRGB8_ALPHA8:i.RGBA8),V===i.UNSIGNED_SHORT&&dt&&(Z=dt.RGBA16_EXT),V===i.SHORT&&dt&&(Z=dt.RGBA16_SNORM_EXT),V===i.UNSIGNED_SHORT_4_4_4_4&&(Z=i.RGBA4),V===i.UNSIGNED_SHORT_5_5_5_1&&(Z=i.RGB5_A1)}return(Z===i.R16F||Z===i.R32F||Z===i.RG16F||Z===i.RG32F||Z===i.RGBA16F||Z===i.RGBA32F)&&t.get("EXT_color_buffer_float"),Z}function g(L,T){let V;return L?T===null||T===wn||T===_a?V=i.DEPTH24_STENCIL8:T===bn?V=i.DEPTH32F_STENCIL8:T===Yi&&(V=i.DEPTH24_STENCIL8,Dt("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):T===null||T===wn||T===_a?V=i.DEPTH_COMPONENT24:T===bn?V=i.DEPTH_COMPONENT32F:T===Yi&&(V=i.DEPTH_COMPONENT16),V}function M(L,T){return w(L)===!0||L.isFramebufferTexture&&L.minFilter!==Pe&&L.minFilter!==gn?Math.log2(Math.max(T.width,T.height))+1:L.mipmaps.length>0?L.mipmaps.length:L.isCompressedTexture&&Array.isArray(L.image)?T.mipmaps.length:1}function E(L){let T=new WeakRef(L);n.get(L).__ref=T,b.add(T),_.register(L,T,T)}function A(L){let T=n.get(L).__ref;T!==void 0&&(b.delete(T),_.unregister(T))}function I(L){P(L.target)}function C(L){N(L.target)}function P(L){L.removeEventListener("dispose",I),A(L),z(L),L.isVideoTexture&&h.delete(L),L.isHTMLTexture&&u.delete(L)}function N(L){L.removeEventListener("dispose",C),A(L),K(L)}function U(){for(let L of b){let T=L.deref();T!==void 0&&(T.isRenderTarget===!0?N(T):P(T))}b.clear(),u.clear()}function z(L){let T=n.get(L);if(T.__webglInit===void 0)return;let V=L.source,at=f.get(V);if(at){let $=at[T.__cacheKey];$.usedTimes--,$.usedTimes===0&&F(L),Object.keys(at).length===0&&f.delete(V)}n.remove(L)}function F(L){let T=n.get(L);i.deleteTexture(T.__webglTexture);let V=L.source,at=f.get(V);delete at[T.__cacheKey],r.memory.textures--}function K(L){let T=n.get(L);T.__depthDisposeCallback&&T.__depthDisposeCallback();let V=L.depthTexture;if(V&&V.renderTarget===L&&P(V),L.isWebGLCubeRenderTarget)for(let $=0;$<6;$++){if(Array.isArray(T.__webglFramebuffer[$]))for(let rt=0;rt<T.__webglFramebuffer[$].length;rt++)i.deleteFramebuffer(T.__webglFramebuffer[$][rt]);else i.deleteFramebuffer(T.__webglFramebuffer[$]);T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer[$])}else{if(Array.isArray(T.__webglFramebuffer))for(let $=0;$<T.__webglFramebuffer.length;$++)i.deleteFramebuffer(T.__webglFramebuffer[$]);else i.deleteFramebuffer(T.__webglFramebuffer);if(T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer),T.__webglMultisampledFramebuffer&&i.deleteFramebuffer(T.__webglMultisampledFramebuffer),T.__webglColorRenderbuffer)for(let $=0;$<T.__webglColorRenderbuffer.length;$++)T.__webglColorRenderbuffer[$]&&i.deleteRenderbuffer(T.__webglColorRenderbuffer[$]);T.__webglDepthRenderbuffer&&i.deleteRenderbuffer(T.__webglDepthRenderbuffer)}let at=L.textures;for(let $=0,rt=at.length;$<rt;$++){let dt=n.get(at[$]);dt.__webglTexture&&(i.deleteTexture(dt.__webglTexture),r.memory.textures--),n.remove(at[$])}n.remove(L)}let H=0;function J(){H=0}function tt(){return H}function ft(L){H=L}function Ct(){let L=H;return L>=a.maxTextures&&Dt("WebGLTextures: Trying to use "+(L+1)+" texture units while this GPU supports only "+a.maxTextures),H+=1,L}function q(L){let T=[];return T.push(L.wrapS),T.push(L.wrapT),T.push(L.wrapR||0),T.push(L.magFilter),T.push(L.minFilter),T.push(L.anisotropy),T.push(L.internalFormat),T.push(L.format),T.push(L.type),T.push(L.generateMipmaps),T.push(L.mipmapsAutoUpdate),T.push(L.premultiplyAlpha),T.push(L.flipY),T.push(L.unpackAlignment),T.push(L.colorSpace),T.join()}function st(L,T){let V=n.get(L);if(L.isVideoTexture&&de(L),L.isRenderTargetTexture===!1&&L.isExternalTexture!==!0&&L.version>0&&V.__version!==L.version){let at=L.image;if(at===null)Dt("WebGLRenderer: Texture marked for update but no image data found.");else if(at.complete===!1)Dt("WebGLRenderer: Texture marked for update but image is incomplete");else{et(V,L,T);return}}else L.isExternalTexture&&(V.__webglTexture=L.sourceTexture?L.sourceTexture:null);e.bindTexture(i.TEXTURE_2D,V.__webglTexture,i.TEXTURE0+T)}function xt(L,T){let V=n.get(L);if(L.isRenderTargetTexture===!1&&L.version>0&&V.__version!==L.version){et(V,L,T);return}else L.isExternalTexture&&(V.__webglTexture=L.sourceTexture?L.sourceTexture:null);e.bindTexture(i.TEXTURE_2D_ARRAY,V.__webglTexture,i.TEXTURE0+T)}function It(L,T){let V=n.get(L);if(L.isRenderTargetTexture===!1&&L.version>0&&V.__version!==L.version){et(V,L,T);return}e.bindTexture(i.TEXTURE_3D,V.__webglTexture,i.TEXTURE0+T)}function mt(L,T){let V=n.get(L);if(L.version>0&&V.__version!==L.version){vt(V,L,T);return}e.bindTexture(i.TEXTURE_CUBE_MAP,V.__webglTexture,i.TEXTURE0+T)}let Ot={[Go]:i.REPEAT,[ai]:i.CLAMP_TO_EDGE,[Wo]:i.MIRRORED_REPEAT},Me={[Pe]:i.NEAREST,[Df]:i.NEAREST_MIPMAP_NEAREST,[Er]:i.NEAREST_MIPMAP_LINEAR,[gn]:i.LINEAR,[yc]:i.LINEAR_MIPMAP_NEAREST,[Ci]:i.LINEAR_MIPMAP_LINEAR},Lt={[Bf]:i.NEVER,[$h]:i.ALWAYS,[kf]:i.LESS,[Zh]:i.LEQUAL,[zf]:i.EQUAL,[Qh]:i.GEQUAL,[Vf]:i.GREATER,[Hf]:i.NOTEQUAL};function $t(L,T){if(T.type===bn&&t.has("OES_texture_float_linear")===!1&&(T.magFilter===gn||T.magFilter===yc||T.magFilter===Er||T.magFilter===Ci||T.minFilter===gn||T.minFilter===yc||T.minFilter===Er||T.minFilter===Ci)&&Dt("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(L,i.TEXTURE_WRAP_S,Ot[T.wrapS]),i.texParameteri(L,i.TEXTURE_WRAP_T,Ot[T.wrapT]),(L===i.TEXTURE_3D||L===i.TEXTURE_2D_ARRAY)&&i.texParameteri(L,i.TEXTURE_WRAP_R,Ot[T.wrapR]),i.texParameteri(L,i.TEXTURE_MAG_FILTER,Me[T.magFilter]),i.texParameteri(L,i.TEXTURE_MIN_FILTER,Me[T.minFilter]),T.compareFunction&&(i.texParameteri(L,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(L,i.TEXTURE_COMPARE_FUNC,Lt[T.compareFunction])),t.has("EXT_texture_filter_anisotropic")===!0){if(T.magFilter===Pe||T.minFilter!==Er&&T.minFilter!==Ci||T.type===bn&&t.has("OES_texture_float_linear")===!1)return;if(T.anisotropy>1||n.get(T).__currentAnisotropy){let V=t.get("EXT_texture_filter_anisotropic");i.texParameterf(L,V.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(T.anisotropy,a.getMaxAnisotropy())),n.get(T).__currentAnisotropy=T.anisotropy}}}function Yt(L,T){let V=!1;L.__webglInit===void 0&&(L.__webglInit=!0,T.addEventListener("dispose",I),E(T));let at=T.source,$=f.get(at);$===void 0&&($={},f.set(at,$));let rt=q(T);if(rt!==L.__cacheKey){$[rt]===void 0&&($[rt]={texture:i.createTexture(),usedTimes:0},r.memory.textures++,V=!0),$[rt].usedTimes++;let dt=$[L.__cacheKey];dt!==void 0&&($[L.__cacheKey].usedTimes--,dt.usedTimes===0&&F(T)),L.__cacheKey=rt,L.__webglTexture=$[rt].texture}return V}function qt(L,T,V){return Math.floor(Math.floor(L/V)/T)}function De(L,T,V,at){let rt=L.updateRanges;if(rt.length===0)e.texSubImage2D(i.TEXTURE_2D,0,0,0,T.width,T.height,V,at,T.data);else{rt.sort((D,Q)=>D.start-Q.start);let dt=0;for(let D=1;D<rt.length;D++){let Q=rt[dt],Y=rt[D],nt=Q.start+Q.count,ot=qt(Y.start,T.width,4),ht=qt(Q.start,T.width,4);Y.start<=nt+1&&ot===ht&&qt(Y.start+Y.count-1,T.width,4)===ot?Q.count=Math.max(Q.count,Y.start+Y.count-Q.start):(++dt,rt[dt]=Y)}rt.length=dt+1;let Z=e.getParameter(i.UNPACK_ROW_LENGTH),j=e.getParameter(i.UNPACK_SKIP_PIXELS),ut=e.getParameter(i.UNPACK_SKIP_ROWS);e.pixelStorei(i.UNPACK_ROW_LENGTH,T.width);for(let D=0,Q=rt.length;D<Q;D++){let Y=rt[D],nt=Math.floor(Y.start/4),ot=Math.ceil(Y.count/4),ht=nt%T.width,Rt=Math.floor(nt/T.width),Wt=ot,ct=1;e.pixelStorei(i.UNPACK_SKIP_PIXELS,ht),e.pixelStorei(i.UNPACK_SKIP_ROWS,Rt),e.texSubImage2D(i.TEXTURE_2D,0,ht,Rt,Wt,ct,V,at,T.data)}L.clearUpdateRanges(),e.pixelStorei(i.UNPACK_ROW_LENGTH,Z),e.pixelStorei(i.UNPACK_SKIP_PIXELS,j),e.pixelStorei(i.UNPACK_SKIP_ROWS,ut)}}function et(L,T,V){let at=i.TEXTURE_2D;(T.isDataArrayTexture||T.isCompressedArrayTexture)&&(at=i.TEXTURE_2D_ARRAY),T.isData3DTexture&&(at=i.TEXTURE_3D);let $=Yt(L,T),rt=T.source;e.bindTexture(at,L.__webglTexture,i.TEXTURE0+V);let dt=n.get(rt);if(rt.version!==dt.__version||$===!0){if(e.activeTexture(i.TEXTURE0+V),(typeof ImageBitmap<"u"&&T.image instanceof ImageBitmap)===!1){let ct=Jt.getPrimaries(Jt.workingColorSpace),Pt=T.colorSpace===Pi?null:Jt.getPrimaries(T.colorSpace),Gt=T.colorSpace===Pi||ct===Pt?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Gt)}e.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment);let j=v(T.image,!1,a.maxTextureSize);j=Et(T,j);let ut=s.convert(T.format,T.colorSpace),D=s.convert(T.type),Q=S(T.internalFormat,ut,D,T.normalized,T.colorSpace,T.isVideoTexture);$t(at,T);let Y,nt=T.mipmaps,ot=T.isVideoTexture!==!0,ht=dt.__version===void 0||$===!0,Rt=rt.dataReady,Wt=M(T,j);if(T.isDepthTexture)Q=g(T.format===Ni,T.type),ht&&(ot?e.texStorage2D(i.TEXTURE_2D,1,Q,j.width,j.height):e.texImage2D(i.TEXTURE_2D,0,Q,j.width,j.height,0,ut,D,null));else if(T.isDataTexture)if(nt.length>0){ot&&ht&&e.texStorage2D(i.TEXTURE_2D,Wt,Q,nt[0].width,nt[0].height);for(let ct=0,Pt=nt.length;ct<Pt;ct++)Y=nt[ct],ot?Rt&&e.texSubImage2D(i.TEXTURE_2D,ct,0,0,Y.width,Y.height,ut,D,Y.data):e.texImage2D(i.TEXTURE_2D,ct,Q,Y.width,Y.height,0,ut,D,Y.data);T.generateMipmaps=!1}else ot?(ht&&e.texStorage2D(i.TEXTURE_2D,Wt,Q,j.width,j.height),Rt&&De(T,j,ut,D)):e.texImage2D(i.TEXTURE_2D,0,Q,j.width,j.height,0,ut,D,j.data);else if(T.isCompressedTexture)if(T.isCompressedArrayTexture){ot&&ht&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Wt,Q,nt[0].width,nt[0].height,j.depth);for(let ct=0,Pt=nt.length;ct<Pt;ct++)if(Y=nt[ct],T.format!==xn)if(ut!==null)if(ot){if(Rt)if(T.layerUpdates.size>0){let Gt=ld(Y.width,Y.height,T.format,T.type);for(let yt of T.layerUpdates){let pe=Y.data.subarray(yt*Gt/Y.data.BYTES_PER_ELEMENT,(yt+1)*Gt/Y.data.BYTES_PER_ELEMENT);e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ct,0,0,yt,Y.width,Y.height,1,ut,pe)}}else e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ct,0,0,0,Y.width,Y.height,j.depth,ut,Y.data)}else e.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ct,Q,Y.width,Y.height,j.depth,0,Y.data,0,0);else Dt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else ot?Rt&&e.texSubImage3D(i.TEXTURE_2D_ARRAY,ct,0,0,0,Y.width,Y.height,j.depth,ut,D,Y.data):e.texImage3D(i.TEXTURE_2D_ARRAY,ct,Q,Y.width,Y.height,j.depth,0,ut,D,Y.data);T.layerUpdates.size>0&&T.clearLayerUpdates()}else{ot&&ht&&e.texStorage2D(i.TEXTURE_2D,Wt,Q,nt[0].width,nt[0].height);for(let ct=0,Pt=nt.length;ct<Pt;ct++)Y=nt[ct],T.format!==xn?ut!==null?ot?Rt&&e.compressedTexSubImage2D(i.TEXTURE_2D,ct,0,0,Y.width,Y.height,ut,Y.data):e.compressedTexImage2D(i.TEXTURE_2D,ct,Q,Y.width,Y.height,0,Y.data):Dt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):ot?Rt&&e.texSubImage2D(i.TEXTURE_2D,ct,0,0,Y.width,Y.height,ut,D,Y.data):e.texImage2D(i.TEXTURE_2D,ct,Q,Y.width,Y.height,0,ut,D,Y.data)}else if(T.isDataArrayTexture)if(ot){if(ht&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Wt,Q,j.width,j.height,j.depth),Rt)if(T.layerUpdates.size>0){let ct=ld(j.width,j.height,T.format,T.type);for(let Pt of T.layerUpdates){let Gt=j.data.subarray(Pt*ct/j.data.BYTES_PER_ELEMENT,(Pt+1)*ct/j.data.BYTES_PER_ELEMENT);e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,Pt,j.width,j.height,1,ut,D,Gt)}T.clearLayerUpdates()}else e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,j.width,j.height,j.depth,ut,D,j.data)}else e.texImage3D(i.TEXTURE_2D_ARRAY,0,Q,j.width,j.height,j.depth,0,ut,D,j.data);else if(T.isData3DTexture)ot?(ht&&e.texStorage3D(i.TEXTURE_3D,Wt,Q,j.width,j.height,j.depth),Rt&&e.texSubImage3D(i.TEXTURE_3D,0,0,0,0,j.width,j.height,j.depth,ut,D,j.data)):e.texImage3D(i.TEXTURE_3D,0,Q,j.width,j.height,j.depth,0,ut,D,j.data);else if(T.isFramebufferTexture){if(ht)if(ot)e.texStorage2D(i.TEXTURE_2D,Wt,Q,j.width,j.height);else{let ct=j.width,Pt=j.height;for(let Gt=0;Gt<Wt;Gt++)e.texImage2D(i.TEXTURE_2D,Gt,Q,ct,Pt,0,ut,D,null),ct>>=1,Pt>>=1}}else if(T.isHTMLTexture){if("texElementImage2D"in i){let ct=i.canvas;if(ct.hasAttribute("layoutsubtree")||ct.setAttribute("layoutsubtree","true"),j.parentNode!==ct){ct.appendChild(j),u.add(T),ct.onpaint=Pt=>{let Gt=Pt.changedElements;for(let yt of u)Gt.includes(yt.image)&&(yt.needsUpdate=!0)},ct.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,j);else{let Gt=i.RGBA,yt=i.RGBA,pe=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,Gt,yt,pe,j)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(nt.length>0){if(ot&&ht){let ct=Nt(nt[0]);e.texStorage2D(i.TEXTURE_2D,Wt,Q,ct.width,ct.height)}for(let ct=0,Pt=nt.length;ct<Pt;ct++)Y=nt[ct],ot?Rt&&e.texSubImage2D(i.TEXTURE_2D,ct,0,0,ut,D,Y):e.texImage2D(i.TEXTURE_2D,ct,Q,ut,D,Y);T.generateMipmaps=!1}else if(ot){if(ht){let ct=Nt(j);e.texStorage2D(i.TEXTURE_2D,Wt,Q,ct.width,ct.height)}Rt&&e.texSubImage2D(i.TEXTURE_2D,0,0,0,ut,D,j)}else e.texImage2D(i.TEXTURE_2D,0,Q,ut,D,j);w(T)&&T.mipmapsAutoUpdate===!0&&p(at),dt.__version=rt.version,T.onUpdate&&T.onUpdate(T)}L.__version=T.version}function vt(L,T,V){if(T.image.length!==6)return;let at=Yt(L,T),$=T.source;e.bindTexture(i.TEXTURE_CUBE_MAP,L.__webglTexture,i.TEXTURE0+V);let rt=n.get($);if($.version!==rt.__version||at===!0){e.activeTexture(i.TEXTURE0+V);let dt=Jt.getPrimaries(Jt.workingColorSpace),Z=T.colorSpace===Pi?null:Jt.getPrimaries(T.colorSpace),j=T.colorSpace===Pi||dt===Z?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),e.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,j);let ut=T.isCompressedTexture||T.image[0].isCompressedTexture,D=T.image[0]&&T.image[0].isDataTexture,Q=[];for(let yt=0;yt<6;yt++)!ut&&!D?Q[yt]=v(T.image[yt],!0,a.maxCubemapSize):Q[yt]=D?T.image[yt].image:T.image[yt],Q[yt]=Et(T,Q[yt]);let Y=Q[0],nt=s.convert(T.format,T.colorSpace),ot=s.convert(T.type),ht=S(T.internalFormat,nt,ot,T.normalized,T.colorSpace),Rt=T.isVideoTexture!==!0,Wt=rt.__version===void 0||at===!0,ct=$.dataReady,Pt=M(T,Y);$t(i.TEXTURE_CUBE_MAP,T);let Gt;if(T.isDepthTexture){if(ht=g(T.format===Ni,T.type),Wt)if(Rt)e.texStorage2D(i.TEXTURE_CUBE_MAP,1,ht,Y.width,Y.height);else for(let yt=0;yt<6;yt++)e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,0,ht,Y.width,Y.height,0,nt,ot,null)}else if(ut){Rt&&Wt&&e.texStorage2D(i.TEXTURE_CUBE_MAP,Pt,ht,Y.width,Y.height);for(let yt=0;yt<6;yt++){Gt=Q[yt].mipmaps;for(let pe=0;pe<Gt.length;pe++){let Ve=Gt[pe];T.format!==xn?nt!==null?Rt?ct&&e.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe,0,0,Ve.width,Ve.height,nt,Ve.data):e.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe,ht,Ve.width,Ve.height,0,Ve.data):Dt("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Rt?ct&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe,0,0,Ve.width,Ve.height,nt,ot,Ve.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe,ht,Ve.width,Ve.height,0,nt,ot,Ve.data)}}}else{if(Gt=T.mipmaps,Rt&&Wt){Gt.length>0&&Pt++;let yt=Nt(Q[0]);e.texStorage2D(i.TEXTURE_CUBE_MAP,Pt,ht,yt.width,yt.height)}for(let yt=0;yt<6;yt++)if(D){Rt?ct&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,0,0,0,Q[yt].width,Q[yt].height,nt,ot,Q[yt].data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,0,ht,Q[yt].width,Q[yt].height,0,nt,ot,Q[yt].data);for(let pe=0;pe<Gt.length;pe++){let Oi=Gt[pe].image[yt].image;Rt?ct&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe+1,0,0,Oi.width,Oi.height,nt,ot,Oi.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe+1,ht,Oi.width,Oi.height,0,nt,ot,Oi.data)}}else{Rt?ct&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,0,0,0,nt,ot,Q[yt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,0,ht,nt,ot,Q[yt]);for(let pe=0;pe<Gt.length;pe++){let Ve=Gt[pe];Rt?ct&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe+1,0,0,nt,ot,Ve.image[yt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+yt,pe+1,ht,nt,ot,Ve.image[yt])}}}w(T)&&T.mipmapsAutoUpdate===!0&&p(i.TEXTURE_CUBE_MAP),rt.__version=$.version,T.onUpdate&&T.onUpdate(T)}L.__version=T.version}function At(L,T,V,at,$,rt){let dt=s.convert(V.format,V.colorSpace),Z=s.convert(V.type),j=S(V.internalFormat,dt,Z,V.normalized,V.colorSpace),ut=n.get(T),D=n.get(V);if(D.__renderTarget=T,!ut.__hasExternalTextures){let Q=Math.max(1,T.width>>rt),Y=Math.max(1,T.height>>rt);$===i.TEXTURE_3D||$===i.TEXTURE_2D_ARRAY?e.texImage3D($,rt,j,Q,Y,T.depth,0,dt,Z,null):e.texImage2D($,rt,j,Q,Y,0,dt,Z,null)}e.bindFramebuffer(i.FRAMEBUFFER,L),lt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,at,$,D.__webglTexture,0,te(T)):($===i.TEXTURE_2D||$>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&$<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,at,$,D.__webglTexture,rt),e.bindFramebuffer(i.FRAMEBUFFER,null)}function ne(L,T,V){if(i.bindRenderbuffer(i.RENDERBUFFER,L),T.depthBuffer){let at=T.depthTexture,$=at&&at.isDepthTexture?at.type:null,rt=g(T.stencilBuffer,$),dt=T.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;lt(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,te(T),rt,T.width,T.height):V?i.renderbufferStorageMultisample(i.RENDERBUFFER,te(T),rt,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,rt,T.width,T.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,dt,i.RENDERBUFFER,L)}else{let at=T.textures;for(let $=0;$<at.length;$++){let rt=at[$],dt=s.convert(rt.format,rt.colorSpace),Z=s.convert(rt.type),j=S(rt.internalFormat,dt,Z,rt.normalized,rt.colorSpace);lt(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,te(T),j,T.width,T.height):V?i.renderbufferStorageMultisample(i.RENDERBUFFER,te(T),j,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,j,T.width,T.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function Vt(L,T,V){let at=T.isWebGLCubeRenderTarget===!0;if(e.bindFramebuffer(i.FRAMEBUFFER,L),!(T.depthTexture&&T.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let $=n.get(T.depthTexture);$.__renderTarget=T;let rt=at?T.depthTexture.image[0]:T.depthTexture.image;(!$.__webglTexture||rt.width!==T.width||rt.height!==T.height)&&(rt.width=T.width,rt.height=T.height,T.depthTexture.needsUpdate=!0),at?mt(T.depthTexture,0):st(T.depthTexture,0);let dt=$.__webglTexture,Z=te(T),j=at?i.TEXTURE_CUBE_MAP_POSITIVE_X+V:i.TEXTURE_2D,ut=T.depthTexture.format===Ni?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(T.depthTexture.format===Ei)lt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ut,j,dt,0,Z):i.framebufferTexture2D(i.FRAMEBUFFER,ut,j,dt,0);else if(T.depthTexture.format===Ni)lt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ut,j,dt,0,Z):i.framebufferTexture2D(i.FRAMEBUFFER,ut,j,dt,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function Se(L){let T=n.get(L),V=L.isWebGLCubeRenderTarget===!0;if(T.__boundDepthTexture!==L.depthTexture){let at=L.depthTexture;if(T.__depthDisposeCallback&&T.__depthDisposeCallback(),at){let $=()=>{delete T.__boundDepthTexture,delete T.__depthDisposeCallback,at.removeEventListener("dispose",$)};at.addEventListener("dispose",$),T.__depthDisposeCallback=$}T.__boundDepthTexture=at}if(L.depthTexture&&!T.__autoAllocateDepthBuffer)if(V)for(let at=0;at<6;at++)Vt(T.__webglFramebuffer[at],L,at);else L.texture.mipmaps.length>0?Vt(T.__webglFramebuffer[0],L,0):Vt(T.__webglFramebuffer,L,0);else if(V){T.__webglDepthbuffer=[];for(let at=0;at<6;at++)if(e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[at]),T.__webglDepthbuffer[at]===void 0)T.__webglDepthbuffer[at]=i.createRenderbuffer(),ne(T.__webglDepthbuffer[at],L,!1);else{let $=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,rt=T.__webglDepthbuffer[at];i.bindRenderbuffer(i.RENDERBUFFER,rt),i.framebufferRenderbuffer(i.FRAMEBUFFER,$,i.RENDERBUFFER,rt)}}else if(L.texture.mipmaps.length>0?e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[0]):e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer),T.__webglDepthbuffer===void 0)T.__webglDepthbuffer=i.createRenderbuffer(),ne(T.__webglDepthbuffer,L,!1);else{let $=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,rt=T.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,rt),i.framebufferRenderbuffer(i.FRAMEBUFFER,$,i.RENDERBUFFER,rt)}e.bindFramebuffer(i.FRAMEBUFFER,null)}function xe(L,T,V){let at=n.get(L);T!==void 0&&At(at.__webglFramebuffer,L,L.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),V!==void 0&&Se(L)}function ge(L){let T=L.texture,V=n.get(L),at=n.get(T);L.addEventListener("dispose",C),E(L);let $=L.textures,rt=L.isWebGLCubeRenderTarget===!0,dt=$.length>1;if(dt||(at.__webglTexture===void 0&&(at.__webglTexture=i.createTexture()),at.__version=T.version,r.memory.textures++),rt){V.__webglFramebuffer=[];for(let Z=0;Z<6;Z++)if(T.mipmaps.length>0){V.__webglFramebuffer[Z]=[];for(let j=0;j<T.mipmaps.length;j++)V.__webglFramebuffer[Z][j]=i.createFramebuffer()}else V.__webglFramebuffer[Z]=i.createFramebuffer()}else{if(T.mipmaps.length>0){V.__webglFramebuffer=[];for(let Z=0;Z<T.mipmaps.length;Z++)V.__webglFramebuffer[Z]=i.createFramebuffer()}else V.__webglFramebuffer=i.createFramebuffer();if(dt)for(let Z=0,j=$.length;Z<j;Z++){let ut=n.get($[Z]);ut.__webglTexture===void 0&&(ut.__webglTexture=i.createTexture(),r.memory.textures++)}if(L.samples>0&&lt(L)===!1){V.__webglMultisampledFramebuffer=i.createFramebuffer(),V.__webglColorRenderbuffer=[],e.bindFramebuffer(i.FRAMEBUFFER,V.__webglMultisampledFramebuffer);for(let Z=0;Z<$.length;Z++){let j=$[Z];V.__webglColorRenderbuffer[Z]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,V.__webglColorRenderbuffer[Z]);let ut=s.convert(j.format,j.colorSpace),D=s.convert(j.type),Q=S(j.internalFormat,ut,D,j.normalized,j.colorSpace,L.isXRRenderTarget===!0),Y=te(L);i.renderbufferStorageMultisample(i.RENDERBUFFER,Y,Q,L.width,L.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+Z,i.RENDERBUFFER,V.__webglColorRenderbuffer[Z])}i.bindRenderbuffer(i.RENDERBUFFER,null),L.depthBuffer&&(V.__webglDepthRenderbuffer=i.createRenderbuffer(),ne(V.__webglDepthRenderbuffer,L,!0)),e.bindFramebuffer(i.FRAMEBUFFER,null)}}if(rt){e.bindTexture(i.TEXTURE_CUBE_MAP,at.__webglTexture),$t(i.TEXTURE_CUBE_MAP,T);for(let Z=0;Z<6;Z++)if(T.mipmaps.length>0)for(let j=0;j<T.mipmaps.length;j++)At(V.__webglFramebuffer[Z][j],L,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+Z,j);else At(V.__webglFramebuffer[Z],L,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+Z,0);w(T)?p(i.TEXTURE_CUBE_MAP):T.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,T.mipmaps.length-1),e.unbindTexture()}else if(dt){for(let Z=0,j=$.length;Z<j;Z++){let ut=$[Z],D=n.get(ut),Q=i.TEXTURE_2D;(L.isWebGL3DRenderTarget||L.isWebGLArrayRenderTarget)&&(Q=L.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture(Q,D.__webglTexture),$t(Q,ut),At(V.__webglFramebuffer,L,ut,i.COLOR_ATTACHMENT0+Z,Q,0),w(ut)&&p(Q)}e.unbindTexture()}else{let Z=i.TEXTURE_2D;if((L.isWebGL3DRenderTarget||L.isWebGLArrayRenderTarget)&&(Z=L.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture(Z,at.__webglTexture),$t(Z,T),T.mipmaps.length>0)for(let j=0;j<T.mipmaps.length;j++)At(V.__webglFramebuffer[j],L,T,i.COLOR_ATTACHMENT0,Z,j);else At(V.__webglFramebuffer,L,T,i.COLOR_ATTACHMENT0,Z,0);w(T)?p(Z):T.mipmaps.length>0&&i.texParameteri(Z,i.TEXTURE_MAX_LEVEL,T.mipmaps.length-1),e.unbindTexture()}L.depthBuffer&&Se(L)}function B(L){let T=L.textures;for(let V=0,at=T.length;V<at;V++){let $=T[V];if(w($)&&$.mipmapsAutoUpdate===!0){let rt=y(L),dt=n.get($).__webglTexture;e.bindTexture(rt,dt),p(rt),e.unbindTexture()}}}let Te=[];function ie(L){if(L.samples>0){if(lt(L)===!1){let T=L.textures,V=L.width,at=L.height,$=i.COLOR_BUFFER_BIT,rt=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,dt=n.get(L),Z=T.length>1;if(Z)for(let ut=0;ut<T.length;ut++)e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ut,i.RENDERBUFFER,null),e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ut,i.TEXTURE_2D,null,0);e.bindFramebuffer(i.READ_FRAMEBUFFER,dt.__webglMultisampledFramebuffer),L.texture.mipmaps.length>0?e.bindFramebuffer(i.DRAW_FRAMEBUFFER,dt.__webglFramebuffer[0]):e.bindFramebuffer(i.DRAW_FRAMEBUFFER,dt.__webglFramebuffer);for(let ut=0;ut<T.length;ut++){if(L.resolveDepthBuffer&&(L.depthBuffer&&($|=i.DEPTH_BUFFER_BIT),L.stencilBuffer&&L.resolveStencilBuffer&&($|=i.STENCIL_BUFFER_BIT)),Z){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,dt.__webglColorRenderbuffer[ut]);let D=n.get(T[ut]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,D,0)}i.blitFramebuffer(0,0,V,at,0,0,V,at,$,i.NEAREST),c===!0&&(Te.length=0,Te.push(i.COLOR_ATTACHMENT0+ut),L.depthBuffer&&L.storeMultisampledDepthBuffer===!1&&Te.push(rt),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Te))}if(e.bindFramebuffer(i.READ_FRAMEBUFFER,null),e.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),Z)for(let ut=0;ut<T.length;ut++){e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ut,i.RENDERBUFFER,dt.__webglColorRenderbuffer[ut]);let D=n.get(T[ut]).__webglTexture;e.bindFramebuffer(i.FRAMEBUFFER,dt.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ut,i.TEXTURE_2D,D,0)}e.bindFramebuffer(i.DRAW_FRAMEBUFFER,dt.__webglMultisampledFramebuffer)}else if(L.depthBuffer&&L.storeMultisampledDepthBuffer===!1&&c){let T=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[T])}}}function te(L){return Math.min(a.maxSamples,L.samples)}function lt(L){let T=n.get(L);return L.samples>0&&t.has("WEBGL_multisampled_render_to_texture")===!0&&T.__useRenderToTexture!==!1}function de(L){let T=r.render.frame;h.get(L)!==T&&(h.set(L,T),L.update())}function Et(L,T){let V=L.colorSpace,at=L.format,$=L.type;return L.isCompressedTexture===!0||L.isVideoTexture===!0||V!==Ys&&V!==Pi&&(Jt.getTransfer(V)===ue?(at!==xn||$!==sn)&&Dt("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):Ft("WebGLTextures: Unsupported texture color space:",V)),T}function Nt(L){return typeof HTMLImageElement<"u"&&L instanceof HTMLImageElement?(l.width=L.naturalWidth||L.width,l.height=L.naturalHeight||L.height):typeof VideoFrame<"u"&&L instanceof VideoFrame?(l.width=L.displayWidth,l.height=L.displayHeight):(l.width=L.width,l.height=L.height),l}this.allocateTextureUnit=Ct,this.resetTextureUnits=J,this.getTextureUnits=tt,this.setTextureUnits=ft,this.setTexture2D=st,this.setTexture2DArray=xt,this.setTexture3D=It,this.setTextureCube=mt,this.rebindTextures=xe,this.setupRenderTarget=ge,this.updateRenderTargetMipmap=B,this.updateMultisampleRenderTarget=ie,this.setupDepthRenderbuffer=Se,this.setupFrameBufferTexture=At,this.useMultisampledRTT=lt,this.dispose=U}function Tv(i,t){function e(n,a=Pi){let s,r=Jt.getTransfer(a);if(n===sn)return i.UNSIGNED_BYTE;if(n===_c)return i.UNSIGNED_SHORT_4_4_4_4;if(n===vc)return i.UNSIGNED_SHORT_5_5_5_1;if(n===qh)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===Yh)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===Tr)return i.BYTE;if(n===Ir)return i.SHORT;if(n===Yi)return i.UNSIGNED_SHORT;if(n===cs)return i.INT;if(n===wn)return i.UNSIGNED_INT;if(n===bn)return i.FLOAT;if(n===Kn)return i.HALF_FLOAT;if(n===Jh)return i.ALPHA;if(n===Kh)return i.RGB;if(n===xn)return i.RGBA;if(n===Ei)return i.DEPTH_COMPONENT;if(n===Ni)return i.DEPTH_STENCIL;if(n===Rr)return i.RED;if(n===va)return i.RED_INTEGER;if(n===li)return i.RG;if(n===ls)return i.RG_INTEGER;if(n===hs)return i.RGBA_INTEGER;if(n===Cr||n===Nr||n===Pr||n===Lr)if(r===ue)if(s=t.get("WEBGL_compressed_texture_s3tc_srgb"),s!==null){if(n===Cr)return s.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===Nr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===Pr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===Lr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(s=t.get("WEBGL_compressed_texture_s3tc"),s!==null){if(n===Cr)return s.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===Nr)return s.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===Pr)return s.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===Lr)return s.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===Mc||n===Sc||n===wc||n===Ac)if(s=t.get("WEBGL_compressed_texture_pvrtc"),s!==null){if(n===Mc)return s.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===Sc)return s.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===wc)return s.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===Ac)return s.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===Ec||n===Tc||n===Ic||n===Rc||n===Cc||n===Dr||n===Nc)if(s=t.get("WEBGL_compressed_texture_etc"),s!==null){if(n===Ec||n===Tc)return r===ue?s.COMPRESSED_SRGB8_ETC2:s.COMPRESSED_RGB8_ETC2;if(n===Ic)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:s.COMPRESSED_RGBA8_ETC2_EAC;if(n===Rc)return s.COMPRESSED_R11_EAC;if(n===Cc)return s.COMPRESSED_SIGNED_R11_EAC;if(n===Dr)return s.COMPRESSED_RG11_EAC;if(n===Nc)return s.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===Pc||n===Lc||n===Dc||n===Uc||n===Oc||n===Fc||n===Bc||n===kc||n===zc||n===Vc||n===Hc||n===Gc||n===Wc||n===jc)if(s=t.get("WEBGL_compressed_texture_astc"),s!==null){if(n===Pc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:s.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===Lc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:s.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===Dc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:s.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===Uc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:s.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===Oc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:s.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===Fc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:s.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===Bc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:s.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===kc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:s.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===zc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:s.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===Vc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:s.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===Hc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:s.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===Gc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:s.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===Wc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:s.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===jc)return r===ue?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:s.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===Xc||n===qc||n===Yc)if(s=t.get("EXT_texture_compression_bptc"),s!==null){if(n===Xc)return r===ue?s.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:s.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===qc)return s.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===Yc)return s.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===Jc||n===Kc||n===Ur||n===Zc)if(s=t.get("EXT_texture_compression_rgtc"),s!==null){if(n===Jc)return s.COMPRESSED_RED_RGTC1_EXT;if(n===Kc)return s.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Ur)return s.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===Zc)return s.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===_a?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:e}}function Nv(i,t){function e(m,x){m.matrixAutoUpdate===!0&&m.updateMatrix(),x.value.copy(m.matrix)}function n(m,x){x.color.getRGB(m.fogColor.value,rd(i)),x.isFog?(m.fogNear.value=x.near,m.fogFar.value=x.far):x.isFogExp2&&(m.fogDensity.value=x.density)}function a(m,x,v,w,p){x.isNodeMaterial?x.uniformsNeedUpdate=!1:x.isMeshBasicMaterial?s(m,x):x.isMeshLambertMaterial?(s(m,x),x.envMap&&(m.envMapIntensity.value=x.envMapIntensity)):x.isMeshToonMaterial?(s(m,x),u(m,x)):x.isMeshPhongMaterial?(s(m,x),h(m,x),x.envMap&&(m.envMapIntensity.value=x.envMapIntensity)):x.isMeshStandardMaterial?(s(m,x),d(m,x),x.isMeshPhysicalMaterial&&f(m,x,p)):x.isMeshMatcapMaterial?(s(m,x),b(m,x)):x.isMeshDepthMaterial?s(m,x):x.isMeshDistanceMaterial?(s(m,x),_(m,x)):x.isMeshNormalMaterial?s(m,x):x.isLineBasicMaterial?(r(m,x),x.isLineDashedMaterial&&o(m,x)):x.isPointsMaterial?c(m,x,v,w):x.isSpriteMaterial?l(m,x):x.isShadowMaterial?(m.color.value.copy(x.color),m.opacity.value=x.opacity):x.isShaderMaterial&&(x.uniformsNeedUpdate=!1)}function s(m,x){m.opacity.value=x.opacity,x.color&&m.diffuse.value.copy(x.color),x.emissive&&m.emissive.value.copy(x.emissive).multiplyScalar(x.emissiveIntensity),x.map&&(m.map.value=x.map,e(x.map,m.mapTransform)),x.alphaMap&&(m.alphaMap.value=x.alphaMap,e(x.alphaMap,m.alphaMapTransform)),x.bumpMap&&(m.bumpMap.value=x.bumpMap,e(x.bumpMap,m.bumpMapTransform),m.bumpScale.value=x.bumpScale,x.side===Xe&&(m.bumpScale.value*=-1)),x.normalMap&&(m.normalMap.value=x.normalMap,e(x.normalMap,m.normalMapTransform),m.normalScale.value.copy(x.normalScale),x.side===Xe&&m.normalScale.value.negate()),x.displacementMap&&(m.displacementMap.value=x.displacementMap,e(x.displacementMap,m.displacementMapTransform),m.displacementScale.value=x.displacementScale,m.displacementBias.value=x.displacementBias),x.emissiveMap&&(m.emissiveMap.value=x.emissiveMap,e(x.emissiveMap,m.emissiveMapTransform)),x.specularMap&&(m.specularMap.value=x.specularMap,e(x.specularMap,m.specularMapTransform)),x.alphaTest>0&&(m.alphaTest.value=x.alphaTest);let v=t.get(x),w=v.envMap,p=v.envMapRotation;w&&(m.envMap.value=w,m.envMapRotation.value.setFromMatrix4(Cv.makeRotationFromEuler(p)).transpose(),w.isCubeTexture&&w.isRenderTargetTexture===!1&&m.envMapRotation.value.premultiply(Tp),m.reflectivity.value=x.reflectivity,m.ior.value=x.ior,m.refractionRatio.value=x.refractionRatio),x.lightMap&&(m.lightMap.value=x.lightMap,m.lightMapIntensity.value=x.lightMapIntensity,e(x.lightMap,m.lightMapTransform)),x.aoMap&&(m.aoMap.value=x.aoMap,m.aoMapIntensity.value=x.aoMapIntensity,e(x.aoMap,m.aoMapTransform))}function r(m,x){m.diffuse.value.copy(x.color),m.opacity.value=x.opacity,x.map&&(m.map.value=x.map,e(x.map,m.mapTransform))}function o(m,x){m.dashSize.value=x.dashSize,m.totalSize.value=x.dashSize+x.gapSize,m.scale.value=x.scale}function c(m,x,v,w){m.diffuse.value.copy(x.color),m.opacity.value=x.opacity,m.size.value=x.size*v,m.scale.value=w*.5,x.map&&(m.map.value=x.map,e(x.map,m.uvTransform)),x.alphaMap&&(m.alphaMap.value=x.alphaMap,e(x.alphaMap,m.alphaMapTransform)),x.alphaTest>0&&(m.alphaTest.value=x.alphaTest)}function l(m,x){m.diffuse.value.copy(x.color),m.opacity.value=x.opacity,m.rotation.value=x.rotation,x.map&&(m.map.value=x.map,e(x.map,m.mapTransform)),x.alphaMap&&(m.alphaMap.value=x.alphaMap,e(x.alphaMap,m.alphaMapTransform)),x.alphaTest>0&&(m.alphaTest.value=x.alphaTest)}function h(m,x){m.specular.value.copy(x.specular),m.shininess.value=Math.max(x.shininess,1e-4)}function u(m,x){x.gradientMap&&(m.gradientMap.value=x.gradientMap)}function d(m,x){m.metalness.value=x.metalness,x.metalnessMap&&(m.metalnessMap.value=x.metalnessMap,e(x.metalnessMap,m.metalnessMapTransform)),m.roughness.value=x.roughness,x.roughnessMap&&(m.roughnessMap.value=x.roughnessMap,e(x.roughnessMap,m.roughnessMapTransform)),x.envMap&&(m.envMapIntensity.value=x.envMapIntensity)}function f(m,x,v){m.ior.value=x.ior,x.diffuseRoughness>0&&(m.diffuseRoughness.value=x.diffuseRoughness,x.diffuseRoughnessMap&&(m.diffuseRoughnessMap.value=x.diffuseRoughnessMap,e(x.diffuseRoughnessMap,m.diffuseRoughnessMapTransform))),x.sheen>0&&(m.sheenColor.value.copy(x.sheenColor).multiplyScalar(x.sheen),m.sheenRoughness.value=x.sheenRoughness,x.sheenColorMap&&(m.sheenColorMap.value=x.sheenColorMap,e(x.sheenColorMap,m.sheenColorMapTransform)),x.sheenRoughnessMap&&(m.sheenRoughnessMap.value=x.sheenRoughnessMap,e(x.sheenRoughnessMap,m.sheenRoughnessMapTransform))),x.clearcoat>0&&(m.clearcoat.value=x.clearcoat,m.clearcoatRoughness.value=x.clearcoatRoughness,x.clearcoatMap&&(m.clearcoatMap.value=x.clearcoatMap,e(x.clearcoatMap,m.clearcoatMapTransform)),x.clearcoatRoughnessMap&&(m.clearcoatRoughnessMap.value=x.clearcoatRoughnessMap,e(x.clearcoatRoughnessMap,m.clearcoatRoughnessMapTransform)),x.clearcoatNormalMap&&(m.clearcoatNormalMap.value=x.clearcoatNormalMap,e(x.clearcoatNormalMap,m.clearcoatNormalMapTransform),m.clearcoatNormalScale.value.copy(x.clearcoatNormalScale),x.side===Xe&&m.clearcoatNormalScale.value.negate())),x.dispersion>0&&(m.dispersion.value=x.dispersion),x.retroreflectivity>0&&(m.retroreflectivity.value=x.retroreflectivity),x.iridescence>0&&(m.iridescence.value=x.iridescence,m.iridescenceIOR.value=x.iridescenceIOR,m.iridescenceThicknessMinimum.value=x.iridescenceThicknessMinimum,m.iridescenceThicknessMaximum.value=x.iridescenceThicknessMaximum,x.iridescenceMap&&(m.iridescenceMap.value=x.iridescenceMap,e(x.iridescenceMap,m.iridescenceMapTransform)),x.iridescenceThicknessMap&&(m.iridescenceThicknessMap.value=x.iridescenceThicknessMap,e(x.iridescenceThicknessMap,m.iridescenceThicknessMapTransform))),x.transmission>0&&(m.transmission.value=x.transmission,m.transmissionSamplerMap.value=v.texture,m.transmissionSamplerSize.value.set(v.width,v.height),x.transmissionMap&&(m.transmissionMap.value=x.transmissionMap,e(x.transmissionMap,m.transmissionMapTransform)),m.thickness.value=x.thickness,x.thicknessMap&&(m.thicknessMap.value=x.thicknessMap,e(x.thicknessMap,m.thicknessMapTransform)),m.attenuationDistance.value=x.attenuationDistance,m.attenuationColor.value.copy(x.attenuationColor)),x.anisotropy>0&&(m.anisotropyVector.value.set(x.anisotropy*Math.cos(x.anisotropyRotation),x.anisotropy*Math.sin(x.anisotropyRotation)),x.anisotropyMap&&(m.anisotropyMap.value=x.anisotropyMap,e(x.anisotropyMap,m.anisotropyMapTransform))),m.specularIntensity.value=x.specularIntensity,m.specularColor.value.copy(x.specularColor),x.specularColorMap&&(m.specularColorMap.value=x.specularColorMap,e(x.specularColorMap,m.specularColorMapTransform)),x.specularIntensityMap&&(m.specularIntensityMap.value=x.specularIntensityMap,e(x.specularIntensityMap,m.specularIntensityMapTransform))}function b(m,x){x.matcap&&(m.matcap.value=x.matcap)}function _(m,x){let v=t.get(x).light;m.referencePosition.value.setFromMatrixPosition(v.matrixWorld),m.nearDistance.value=v.shadow.camera.near,m.farDistance.value=v.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:a}}function Pv(i,t,e,n){let a={},s={};function r(v,w){let p=w.program;n.uniformBlockBinding(v,p,a[v.id])}function o(v,w){let p=a[v.id];p===void 0&&(b(v),p=c(v),a[v.id]=p,v.addEventListener("dispose",m));let y=w.program;n.updateUBOMapping(v,y);let S=t.render.frame;s[v.id]!==S&&(l(v),s[v.id]=S)}function c(v){let w=i.createBuffer(),p=v.__size,y=v.usage;return i.bindBuffer(i.UNIFORM_BUFFER,w),i.bufferData(i.UNIFORM_BUFFER,p,y),i.bindBuffer(i.UNIFORM_BUFFER,null),w}function l(v){let w=a[v.id],p=v.uniforms,y=v.__cache;i.bindBuffer(i.UNIFORM_BUFFER,w);for(let S=0,g=p.length;S<g;S++){let M=p[S];if(Array.isArray(M))for(let E=0,A=M.length;E<A;E++)h(M[E],S,E,y);else h(M,S,0,y)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(v,w,p,y){if(d(v,w,p,y)===!0){let S=v.__offset,g=v.value;if(Array.isArray(g)){let M=0;for(let E=0;E<g.length;E++){let A=g[E],I=_(A,!0);u(A,v.__data,M),M+=I.storage/Float32Array.BYTES_PER_ELEMENT}}else u(g,v.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,S,v.__data)}}function u(v,w,p){typeof v=="number"||typeof v=="boolean"?w[p]=v:v.isMatrix3?(w[p]=v.elements[0],w[p+1]=v.elements[1],w[p+2]=v.elements[2],w[p+3]=0,w[p+4]=v.elements[3],w[p+5]=v.elements[4],w[p+6]=v.elements[5],w[p+7]=0,w[p+8]=v.elements[6],w[p+9]=v.elements[7],w[p+10]=v.elements[8],w[p+11]=0):ArrayBuffer.isView(v)?w.set(v.subarray(0,w.length-p),p):v.toArray(w,p)}function d(v,w,p,y){let S=v.value,g=w+"_"+p;if(Array.isArray(S)){y[g]===void 0&&(y[g]=[]);let M=y[g],E=!1;for(let A=0;A<S.length;A++)f(S[A],M,A)===!0&&(E=!0);return E}return f(S,y,g)}function f(v,w,p){if(w[p]===void 0)return typeof v=="number"||typeof v=="boolean"?w[p]=v:ArrayBuffer.isView(v)?w[p]=v.slice():w[p]=v.clone(),!0;{let y=w[p];if(typeof v=="number"||typeof v=="boolean"){if(y!==v)return w[p]=v,!0}else{if(ArrayBuffer.isView(v))return!0;if(y.equals(v)===!1)return y.copy(v),!0}}return!1}function b(v){let w=v.uniforms,p=0,y=16;for(let g=0,M=w.length;g<M;g++){let E=Array.isArray(w[g])?w[g]:[w[g]];for(let A=0,I=E.length;A<I;A++){let C=E[A],P=Array.isArray(C.value)?C.value:[C.value],N=Array.isArray(w[g])||Array.isArray(C.value),U=p;for(let F=0,K=P.length;F<K;F++){let H=P[F],J=_(H,N),tt=p%y,ft=tt%J.boundary,Ct=tt+ft;p+=ft,Ct!==0&&y-Ct<J.storage&&(p+=y-Ct),F===0&&(U=p),p+=J.storage}let z=C.type==="int"?Int32Array:C.type==="uint"?Uint32Array:Float32Array;C.__data=new z((p-U)/Float32Array.BYTES_PER_ELEMENT),C.__offset=U}}let S=p%y;return S>0&&(p+=y-S),v.__size=p,v.__cache={},this}function _(v,w){let p={boundary:0,storage:0};return typeof v=="number"||typeof v=="boolean"?(p.boundary=4,p.storage=4):v.isVector2?(p.boundary=8,p.storage=8):v.isVector3||v.isColor?(p.boundary=16,p.storage=12):v.isVector4?(p.boundary=16,p.storage=16):v.isMatrix3?(p.boundary=16,p.storage=48):v.isMatrix4?(p.boundary=16,p.storage=64):v.isTexture?Dt("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(v)?(p.boundary=16,p.storage=v.byteLength):Dt("WebGLRenderer: Unsupported uniform value type.",v),w===!0&&(p.boundary=16,p.storage=Math.ceil(p.storage/16)*16),p}function m(v){let w=v.target;w.removeEventListener("dispose",m),i.deleteBuffer(a[w.id]),delete a[w.id],delete s[w.id]}function x(){for(let v in a)i.deleteBuffer(a[v]);a={},s={}}return{bind:r,update:o,dispose:x}}function Dv(){return hi===null&&(hi=new Ai(Lv,16,16,li,Kn),hi.name="DFG_LUT",hi.minFilter=gn,hi.magFilter=gn,hi.wrapS=ai,hi.wrapT=ai,hi.generateMipmaps=!1,hi.needsUpdate=!0),hi}var Zb,Qb,$b,tx,ex,nx,ix,ax,sx,rx,ox,cx,lx,hx,dx,ux,fx,px,mx,gx,bx,xx,yx,_x,vx,Mx,Sx,wx,Ax,Ex,Tx,Ix,Rx,Cx,Nx,Px,Lx,Dx,Ux,Ox,Fx,Bx,kx,zx,Vx,Hx,Gx,Wx,jx,Xx,qx,Yx,Jx,Kx,Zx,Qx,$x,t0,e0,n0,i0,a0,s0,r0,o0,c0,l0,h0,d0,u0,f0,p0,m0,g0,b0,x0,y0,_0,v0,M0,S0,w0,A0,E0,T0,I0,R0,C0,N0,P0,L0,D0,U0,O0,F0,B0,k0,z0,V0,H0,G0,W0,j0,X0,q0,Y0,J0,K0,Z0,Q0,$0,ty,ey,ny,iy,ay,sy,ry,oy,cy,ly,hy,dy,uy,fy,py,my,gy,by,xy,yy,_y,vy,My,Sy,wy,Ay,Ey,Ty,Iy,Ry,jt,bt,yn,tl,Cy,xp,kr,Kf,Oy,Fy,yp,_p,By,ky,zy,nl,Zy,vp,Mp,Sp,wp,Ap,Ep,tp,ep,np,ip,ap,xd,yd,_d,gd,ds,z_,V_,op,j_,el,Z_,$_,ev,iv,sv,cv,Md,Sd,gv,_v,vv,Mv,Sv,gp,Fr,bd,Iv,Rv,wd,Ad,Cv,Tp,Lv,hi,il,fs=ca(()=>{md();md();Zb=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,Qb=`#ifdef USE_ALPHAHASH
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
#endif`,$b=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,tx=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,ex=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,nx=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,ix=`#ifdef USE_AOMAP
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
#endif`,ax=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,sx=`#ifdef USE_BATCHING
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
#endif`,rx=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,ox=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,cx=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,lx=`float G_BlinnPhong_Implicit( ) {
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
} // validated`,hx=`#ifdef USE_IRIDESCENCE
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
#endif`,dx=`#ifdef USE_BUMPMAP
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
#endif`,ux=`#if NUM_CLIPPING_PLANES > 0
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
#endif`,fx=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,px=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,mx=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,gx=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,bx=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,xx=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,yx=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
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
#endif`,_x=`#define PI 3.141592653589793
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
} // validated`,vx=`vec3 transformedNormal = objectNormal;
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
#endif`,Mx=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,Sx=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,wx=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,Ax=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,Ex="gl_FragColor = linearToOutputTexel( gl_FragColor );",Tx=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,Ix=`#ifdef USE_ENVMAP
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
#endif`,Rx=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,Cx=`#ifdef USE_ENVMAP
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
#endif`,Nx=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,Px=`#ifdef USE_ENVMAP
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
#endif`,Lx=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,Dx=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,Ux=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,Ox=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,Fx=`#ifdef USE_GRADIENTMAP
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
}`,Bx=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,kx=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,zx=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,Vx=`uniform bool receiveShadow;
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
#include <lightprobes_pars_fragment>`,Hx=`#ifdef USE_ENVMAP
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
#endif`,Gx=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,Wx=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,jx=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Xx=`varying vec3 vViewPosition;
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
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,qx=`PhysicalMaterial material;
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
#endif`,Yx=`uniform sampler2D dfgLUT;
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
}`,Jx=`
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
#endif`,Kx=`#if defined( RE_IndirectDiffuse )
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
#endif`,Zx=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,Qx=`#if NUM_LIGHT_PROBE_GRIDS > 0
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
#endif`,$x=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,t0=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,e0=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,n0=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,i0=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,a0=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,s0=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
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
#endif`,r0=`#if defined( USE_POINTS_UV )
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
#endif`,o0=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,c0=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,l0=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,h0=`#if defined( USE_MORPHCOLORS )
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
#endif`,d0=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,u0=`#ifdef USE_MORPHTARGETS
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
#endif`,f0=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,p0=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
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
vec3 nonPerturbedNormal = normal;`,m0=`#ifdef USE_NORMALMAP_OBJECTSPACE
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
#endif`,g0=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,b0=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,x0=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,y0=`#ifdef USE_NORMALMAP
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
#endif`,_0=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,v0=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,M0=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,S0=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,w0=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,A0=`vec3 packNormalToRGB( const in vec3 normal ) {
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
}`,E0=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,T0=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,I0=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,R0=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,C0=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,N0=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,P0=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,L0=`#if NUM_SPOT_LIGHT_COORDS > 0
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
#endif`,D0=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
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
#endif`,U0=`float getShadowMask() {
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
}`,O0=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,F0=`#ifdef USE_SKINNING
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
#endif`,B0=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,k0=`#ifdef USE_SKINNING
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
#endif`,z0=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,V0=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,H0=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,G0=`#ifndef saturate
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
vec3 CustomToneMapping( vec3 color ) { return color; }`,W0=`#ifdef USE_TRANSMISSION
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
#endif`,j0=`#ifdef USE_TRANSMISSION
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
#endif`,X0=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,q0=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,Y0=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
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
#endif`,J0=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,K0=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,Z0=`uniform sampler2D t2D;
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
}`,Q0=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,$0=`uniform float backgroundBlurriness;
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
}`,ty=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,ey=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,ny=`#include <common>
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
}`,iy=`#if DEPTH_PACKING == 3200
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
}`,ay=`#define DISTANCE
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
}`,sy=`#define DISTANCE
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
}`,ry=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,oy=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,cy=`uniform float scale;
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
}`,ly=`uniform vec3 diffuse;
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
}`,hy=`#include <common>
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
}`,dy=`uniform vec3 diffuse;
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
}`,uy=`#define LAMBERT
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
}`,fy=`#define LAMBERT
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
}`,py=`#define MATCAP
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
}`,my=`#define MATCAP
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
}`,gy=`#define NORMAL
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
}`,by=`#define NORMAL
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
}`,xy=`#define PHONG
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
}`,yy=`#define PHONG
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
}`,_y=`#define STANDARD
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
}`,vy=`#define STANDARD
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
}`,My=`#define TOON
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
}`,Sy=`#define TOON
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
}`,wy=`uniform float size;
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
}`,Ay=`uniform vec3 diffuse;
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
}`,Ey=`#include <common>
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
}`,Ty=`uniform vec3 color;
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
}`,Iy=`uniform float rotation;
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
}`,Ry=`uniform vec3 diffuse;
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
}`,jt={alphahash_fragment:Zb,alphahash_pars_fragment:Qb,alphamap_fragment:$b,alphamap_pars_fragment:tx,alphatest_fragment:ex,alphatest_pars_fragment:nx,aomap_fragment:ix,aomap_pars_fragment:ax,batching_pars_vertex:sx,batching_vertex:rx,begin_vertex:ox,beginnormal_vertex:cx,bsdfs:lx,iridescence_fragment:hx,bumpmap_pars_fragment:dx,clipping_planes_fragment:ux,clipping_planes_pars_fragment:fx,clipping_planes_pars_vertex:px,clipping_planes_vertex:mx,color_fragment:gx,color_pars_fragment:bx,color_pars_vertex:xx,color_vertex:yx,common:_x,defaultnormal_vertex:vx,displacementmap_pars_vertex:Mx,displacementmap_vertex:Sx,emissivemap_fragment:wx,emissivemap_pars_fragment:Ax,colorspace_fragment:Ex,colorspace_pars_fragment:Tx,envmap_fragment:Ix,envmap_common_pars_fragment:Rx,envmap_pars_fragment:Cx,envmap_pars_vertex:Nx,envmap_physical_pars_fragment:Hx,envmap_vertex:Px,fog_vertex:Lx,fog_pars_vertex:Dx,fog_fragment:Ux,fog_pars_fragment:Ox,gradientmap_pars_fragment:Fx,lightmap_pars_fragment:Bx,lights_lambert_fragment:kx,lights_lambert_pars_fragment:zx,lights_pars_begin:Vx,lights_toon_fragment:Gx,lights_toon_pars_fragment:Wx,lights_phong_fragment:jx,lights_phong_pars_fragment:Xx,lights_physical_fragment:qx,lights_physical_pars_fragment:Yx,lights_fragment_begin:Jx,lights_fragment_maps:Kx,lights_fragment_end:Zx,lightprobes_pars_fragment:Qx,logdepthbuf_fragment:$x,logdepthbuf_pars_fragment:t0,logdepthbuf_pars_vertex:e0,logdepthbuf_vertex:n0,map_fragment:i0,map_pars_fragment:a0,map_particle_fragment:s0,map_particle_pars_fragment:r0,metalnessmap_fragment:o0,metalnessmap_pars_fragment:c0,morphinstance_vertex:l0,morphcolor_vertex:h0,morphnormal_vertex:d0,morphtarget_pars_vertex:u0,morphtarget_vertex:f0,normal_fragment_begin:p0,normal_fragment_maps:m0,normal_pars_fragment:g0,normal_pars_vertex:b0,normal_vertex:x0,normalmap_pars_fragment:y0,clearcoat_normal_fragment_begin:_0,clearcoat_normal_fragment_maps:v0,clearcoat_pars_fragment:M0,iridescence_pars_fragment:S0,opaque_fragment:w0,packing:A0,premultiplied_alpha_fragment:E0,project_vertex:T0,dithering_fragment:I0,dithering_pars_fragment:R0,roughnessmap_fragment:C0,roughnessmap_pars_fragment:N0,shadowmap_pars_fragment:P0,shadowmap_pars_vertex:L0,shadowmap_vertex:D0,shadowmask_pars_fragment:U0,skinbase_vertex:O0,skinning_pars_vertex:F0,skinning_vertex:B0,skinnormal_vertex:k0,specularmap_fragment:z0,specularmap_pars_fragment:V0,tonemapping_fragment:H0,tonemapping_pars_fragment:G0,transmission_fragment:W0,transmission_pars_fragment:j0,uv_pars_fragment:X0,uv_pars_vertex:q0,uv_vertex:Y0,worldpos_vertex:J0,background_vert:K0,background_frag:Z0,backgroundCube_vert:Q0,backgroundCube_frag:$0,cube_vert:ty,cube_frag:ey,depth_vert:ny,depth_frag:iy,distance_vert:ay,distance_frag:sy,equirect_vert:ry,equirect_frag:oy,linedashed_vert:cy,linedashed_frag:ly,meshbasic_vert:hy,meshbasic_frag:dy,meshlambert_vert:uy,meshlambert_frag:fy,meshmatcap_vert:py,meshmatcap_frag:my,meshnormal_vert:gy,meshnormal_frag:by,meshphong_vert:xy,meshphong_frag:yy,meshphysical_vert:_y,meshphysical_frag:vy,meshtoon_vert:My,meshtoon_frag:Sy,points_vert:wy,points_frag:Ay,shadow_vert:Ey,shadow_frag:Ty,sprite_vert:Iy,sprite_frag:Ry},bt={common:{diffuse:{value:new Ht(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new Bt},alphaMap:{value:null},alphaMapTransform:{value:new Bt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new Bt}},envmap:{envMap:{value:null},envMapRotation:{value:new Bt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new Bt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new Bt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new Bt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new Bt},normalScale:{value:new Ut(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new Bt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new Bt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new Bt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new Bt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new Ht(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new Ht(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new Bt},alphaTest:{value:0},uvTransform:{value:new Bt}},sprite:{diffuse:{value:new Ht(16777215)},opacity:{value:1},center:{value:new Ut(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new Bt},alphaMap:{value:null},alphaMapTransform:{value:new Bt},alphaTest:{value:0}}},yn={basic:{uniforms:rn([bt.common,bt.specularmap,bt.envmap,bt.aomap,bt.lightmap,bt.fog]),vertexShader:jt.meshbasic_vert,fragmentShader:jt.meshbasic_frag},lambert:{uniforms:rn([bt.common,bt.specularmap,bt.envmap,bt.aomap,bt.lightmap,bt.emissivemap,bt.bumpmap,bt.normalmap,bt.displacementmap,bt.fog,bt.lights,{emissive:{value:new Ht(0)},envMapIntensity:{value:1}}]),vertexShader:jt.meshlambert_vert,fragmentShader:jt.meshlambert_frag},phong:{uniforms:rn([bt.common,bt.specularmap,bt.envmap,bt.aomap,bt.lightmap,bt.emissivemap,bt.bumpmap,bt.normalmap,bt.displacementmap,bt.fog,bt.lights,{emissive:{value:new Ht(0)},specular:{value:new Ht(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:jt.meshphong_vert,fragmentShader:jt.meshphong_frag},standard:{uniforms:rn([bt.common,bt.envmap,bt.aomap,bt.lightmap,bt.emissivemap,bt.bumpmap,bt.normalmap,bt.displacementmap,bt.roughnessmap,bt.metalnessmap,bt.fog,bt.lights,{emissive:{value:new Ht(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:jt.meshphysical_vert,fragmentShader:jt.meshphysical_frag},toon:{uniforms:rn([bt.common,bt.aomap,bt.lightmap,bt.emissivemap,bt.bumpmap,bt.normalmap,bt.displacementmap,bt.gradientmap,bt.fog,bt.lights,{emissive:{value:new Ht(0)}}]),vertexShader:jt.meshtoon_vert,fragmentShader:jt.meshtoon_frag},matcap:{uniforms:rn([bt.common,bt.bumpmap,bt.normalmap,bt.displacementmap,bt.fog,{matcap:{value:null}}]),vertexShader:jt.meshmatcap_vert,fragmentShader:jt.meshmatcap_frag},points:{uniforms:rn([bt.points,bt.fog]),vertexShader:jt.points_vert,fragmentShader:jt.points_frag},dashed:{uniforms:rn([bt.common,bt.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:jt.linedashed_vert,fragmentShader:jt.linedashed_frag},depth:{uniforms:rn([bt.common,bt.displacementmap]),vertexShader:jt.depth_vert,fragmentShader:jt.depth_frag},normal:{uniforms:rn([bt.common,bt.bumpmap,bt.normalmap,bt.displacementmap,{opacity:{value:1}}]),vertexShader:jt.meshnormal_vert,fragmentShader:jt.meshnormal_frag},sprite:{uniforms:rn([bt.sprite,bt.fog]),vertexShader:jt.sprite_vert,fragmentShader:jt.sprite_frag},background:{uniforms:{uvTransform:{value:new Bt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:jt.background_vert,fragmentShader:jt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new Bt}},vertexShader:jt.backgroundCube_vert,fragmentShader:jt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:jt.cube_vert,fragmentShader:jt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:jt.equirect_vert,fragmentShader:jt.equirect_frag},distance:{uniforms:rn([bt.common,bt.displacementmap,{referencePosition:{value:new k},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:jt.distance_vert,fragmentShader:jt.distance_frag},shadow:{uniforms:rn([bt.lights,bt.fog,{color:{value:new Ht(0)},opacity:{value:1}}]),vertexShader:jt.shadow_vert,fragmentShader:jt.shadow_frag}};yn.physical={uniforms:rn([yn.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new Bt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new Bt},clearcoatNormalScale:{value:new Ut(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new Bt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new Bt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new Bt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new Bt},sheen:{value:0},sheenColor:{value:new Ht(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new Bt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new Bt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new Bt},transmissionSamplerSize:{value:new Ut},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new Bt},attenuationDistance:{value:0},attenuationColor:{value:new Ht(0)},specularColor:{value:new Ht(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new Bt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new Bt},anisotropyVector:{value:new Ut},anisotropyMap:{value:null},anisotropyMapTransform:{value:new Bt}}]),vertexShader:jt.meshphysical_vert,fragmentShader:jt.meshphysical_frag};tl={r:0,b:0,g:0},Cy=new se,xp=new Bt;xp.set(-1,0,0,0,1,0,0,0,1);kr=class extends Cn{constructor(t=1,e={}){super(t,t,e),this.isWebGLCubeRenderTarget=!0;let n={width:t,height:t,depth:1},a=[n,n,n,n,n,n];this.texture=new rr(a),this._setTextureOptions(e),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(t,e){this.texture.type=e.type,this.texture.colorSpace=e.colorSpace,this.texture.generateMipmaps=e.generateMipmaps,this.texture.minFilter=e.minFilter,this.texture.magFilter=e.magFilter;let n={uniforms:{tEquirect:{value:null}},vertexShader:`

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
			`},a=new es(5,5,5),s=new Fn({name:"CubemapFromEquirect",uniforms:Sa(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Xe,blending:ba});s.uniforms.tEquirect.value=e;let r=new an(a,s),o=e.minFilter;return e.minFilter===Ci&&(e.minFilter=gn),new is(1,10,this).update(t,r),e.minFilter=o,r.geometry.dispose(),r.material.dispose(),this}clear(t,e=!0,n=!0,a=!0){let s=t.getRenderTarget();for(let r=0;r<6;r++)t.setRenderTarget(this,r),t.clear(e,n,a);t.setRenderTarget(s)}},Kf=256,Oy=3,Fy=20,yp=256,_p=16,By=3,ky=new k,zy=new Ht,nl=class i{constructor(t){this._renderer=t,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new is(1,10,null),this._boxMesh=new an(new es(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(t,e=0,n=.1,a=100,s={}){let{size:r=256,position:o=ky}=s,c=this._renderer;this._setSize(r);let l=this._allocateTarget(),h=this._getSourceTarget(!0);e>0&&(h.texture.mipmapsAutoUpdate=!1);let u=c.autoClear,d=c.autoClearColor,f=c.autoClearDepth,b=c.autoClearStencil,_=t.background;c.autoClear=!0,c.autoClearColor=!0,c.autoClearDepth=!0,c.autoClearStencil=!0,_===null&&(t.background=c.getClearColor(zy));let m=new is(n,a,h);return m.position.copy(o),m.update(c,t),c.autoClear=u,c.autoClearColor=d,c.autoClearDepth=f,c.autoClearStencil=b,t.background=_,e>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(l,e)),this._applyPMREM(l),l}fromEquirectangular(t,e=null){return this._fromTexture(t,e)}fromCubemap(t,e=null){return this._fromTexture(t,e)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=$f(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Qf(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(t,e){return e>0?1-Math.sqrt(1-t/e):0}_setSize(t){this._cubeSize=Math.max(Kf,id(t))}_fromTexture(t,e){t.mapping===ya||t.mapping===os?this._setSize(t.image.length===0?Kf:t.image[0].width||t.image[0].image.width):this._setSize(t.image.width/4);let n=e||this._allocateTarget();return this._textureToCubemap(t),this._applyPMREM(n),n}_allocateTarget(){let t=this._cubeSize,e=Zf(t,!1,!1),n=Math.log2(t)-Oy;for(let a=0;a<=n;a++)e.texture.mipmaps.push({width:t>>a,height:t>>a});return e.texture.name="PMREM",e.texture.isPMREMTexture=!0,e}_getSourceTarget(t=!1){let e=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==e||t&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Zf(e,!0,t)),this._sourceTarget}_compileMaterial(t){this._boxMesh.material=t,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(t,e,n){let a=this._boxMesh,s=this._cubeCamera;a.material=n,s.renderTarget=t,s.activeMipmapLevel=e;let r=t.width>>e;t.viewport.set(0,0,r,r),s.update(this._renderer,a),t.viewport.set(0,0,t.width,t.height)}_textureToCubemap(t){let e;t.mapping===ya||t.mapping===os?(this._cubemapMaterial===null&&(this._cubemapMaterial=$f()),e=this._cubemapMaterial,e.uniforms.flipEnvMap.value=t.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Qf()),e=this._equirectMaterial),e.uniforms.envMap.value=t,this._renderCube(this._getSourceTarget(),0,e)}_applyPMREM(t){this._ggxMaterial===null&&(this._ggxMaterial=Vy(),this._integrationMaterial=Hy());let e=this._cubeSize,n=t.texture.mipmaps.length-1,a=this._ggxMaterial.uniforms;a.envMap.value=this._sourceTarget.texture;let s=this._integrationMaterial.uniforms;s.envMap.value=this._sourceTarget.texture,s.sourceLod.value=Math.log2(e/_p);for(let r=0;r<=n;r++){let o=i.lodToRoughness(r,n);if(r>n-By)s.roughness.value=o,this._renderCube(t,r,this._integrationMaterial);else{let c=o>0?Math.log2(e)+.5*Math.log2(6/(yp*Math.pow(o,4)))+.5:0;a.roughness.value=o,a.lodBias.value=c,this._renderCube(t,r,this._ggxMaterial)}}}_blur(t,e){this._blurMaterial===null&&(this._blurMaterial=Gy());let n=this._blurMaterial,a=n.uniforms,s=this._sourceTarget;a.sigma.value=Math.min(e,Math.PI)/Math.SQRT2,a.envMap.value=s.texture,this._renderCube(t,0,n),a.envMap.value=t.texture,this._renderCube(s,0,n)}};Zy={[kh]:"LINEAR_TONE_MAPPING",[zh]:"REINHARD_TONE_MAPPING",[Vh]:"CINEON_TONE_MAPPING",[Hh]:"ACES_FILMIC_TONE_MAPPING",[Wh]:"AGX_TONE_MAPPING",[jh]:"NEUTRAL_TONE_MAPPING",[Gh]:"CUSTOM_TONE_MAPPING"};vp=new Sn,Mp=new Ri(1,1),Sp=new or(1),wp=new Qs,Ap=new Yo,Ep=new rr,tp=[],ep=[],np=new Float32Array(16),ip=new Float32Array(9),ap=new Float32Array(4);xd=class{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.setValue=x_(e.type)}},yd=class{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.size=e.size,this.setValue=B_(e.type)}},_d=class{constructor(t){this.id=t,this.seq=[],this.map={}}setValue(t,e,n){let a=this.seq;for(let s=0,r=a.length;s!==r;++s){let o=a[s];o.setValue(t,e[o.id],n)}}},gd=/(\w+)(\])?(\[|\.)?/g;ds=class{constructor(t,e){this.seq=[],this.map={};let n=t.getProgramParameter(e,t.ACTIVE_UNIFORMS);for(let r=0;r<n;++r){let o=t.getActiveUniform(e,r),c=t.getUniformLocation(e,o.name);k_(o,c,this)}let a=[],s=[];for(let r of this.seq)r.type===t.SAMPLER_2D_SHADOW||r.type===t.SAMPLER_CUBE_SHADOW||r.type===t.SAMPLER_2D_ARRAY_SHADOW?a.push(r):s.push(r);a.length>0&&(this.seq=a.concat(s))}setValue(t,e,n,a){let s=this.map[e];s!==void 0&&s.setValue(t,n,a)}setOptional(t,e,n){let a=e[n];a!==void 0&&this.setValue(t,n,a)}static upload(t,e,n,a){for(let s=0,r=e.length;s!==r;++s){let o=e[s],c=n[o.id];c.needsUpdate!==!1&&o.setValue(t,c.value,a)}}static seqWithValue(t,e){let n=[];for(let a=0,s=t.length;a!==s;++a){let r=t[a];r.id in e&&n.push(r)}return n}};z_=37297,V_=0;op=new Bt;j_={[kh]:"Linear",[zh]:"Reinhard",[Vh]:"Cineon",[Hh]:"ACESFilmic",[Wh]:"AgX",[jh]:"Neutral",[Gh]:"Custom"};el=new k;Z_=/^[ \t]*#include +<([\w\d./]+)>/gm;$_=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;ev={[Ar]:"SHADOWMAP_TYPE_PCF",[ss]:"SHADOWMAP_TYPE_VSM"};iv={[os]:"ENVMAP_MODE_REFRACTION"};sv={[gc]:"ENVMAP_BLENDING_MULTIPLY",[Pf]:"ENVMAP_BLENDING_MIX",[Lf]:"ENVMAP_BLENDING_ADD"};cv=0,Md=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(t,e,n){let a=this._getShaderCacheForMaterial(t);return a.has(e)===!1&&(a.add(e),e.usedTimes++),a.has(n)===!1&&(a.add(n),n.usedTimes++),this}remove(t){let e=this.materialCache.get(t);for(let n of e)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(t),this}getVertexShaderStage(t){return this._getShaderStage(t.vertexShader)}getFragmentShaderStage(t){return this._getShaderStage(t.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(t){let e=this.materialCache,n=e.get(t);return n===void 0&&(n=new Set,e.set(t,n)),n}_getShaderStage(t){let e=this.shaderCache,n=e.get(t);return n===void 0&&(n=new Sd(t),e.set(t,n)),n}},Sd=class{constructor(t){this.id=cv++,this.code=t,this.usedTimes=0}};gv=0;_v=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,vv=`uniform sampler2D shadow_pass;
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
}`,Mv=[new k(1,0,0),new k(-1,0,0),new k(0,1,0),new k(0,-1,0),new k(0,0,1),new k(0,0,-1)],Sv=[new k(0,-1,0),new k(0,-1,0),new k(0,0,1),new k(0,0,-1),new k(0,-1,0),new k(0,-1,0)],gp=new se,Fr=new k,bd=new k;Iv=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,Rv=`
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

}`,wd=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(t,e){if(this.texture===null){let n=new cr(t.texture);(t.depthNear!==e.depthNear||t.depthFar!==e.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=n}}getMesh(t){if(this.texture!==null&&this.mesh===null){let e=t.cameras[0].viewport,n=new Fn({vertexShader:Iv,fragmentShader:Rv,uniforms:{depthColor:{value:this.texture},depthWidth:{value:e.z},depthHeight:{value:e.w}}});this.mesh=new an(new hr(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Ad=class extends qn{constructor(t,e){super();let n=this,a=null,s=1,r=null,o="local-floor",c=1,l=null,h=null,u=null,d=null,f=null,b=null,_=typeof XRWebGLBinding<"u",m=new wd,x={},v=e.getContextAttributes(),w=null,p=null,y=[],S=[],g=new Ut,M=null,E=null,A=new pn;A.viewport=new re;let I=new pn;I.viewport=new re;let C=[A,I],P=new fc,N=null,U=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(q){let st=y[q];return st===void 0&&(st=new Qa,y[q]=st),st.getTargetRaySpace()},this.getControllerGrip=function(q){let st=y[q];return st===void 0&&(st=new Qa,y[q]=st),st.getGripSpace()},this.getHand=function(q){let st=y[q];return st===void 0&&(st=new Qa,y[q]=st),st.getHandSpace()};function z(q){let st=S.indexOf(q.inputSource);if(st===-1)return;let xt=y[st];xt!==void 0&&(xt.update(q.inputSource,q.frame,l||r),xt.dispatchEvent({type:q.type,data:q.inputSource}))}function F(){a.removeEventListener("select",z),a.removeEventListener("selectstart",z),a.removeEventListener("selectend",z),a.removeEventListener("squeeze",z),a.removeEventListener("squeezestart",z),a.removeEventListener("squeezeend",z),a.removeEventListener("end",F),a.removeEventListener("inputsourceschange",K);for(let q=0;q<y.length;q++){let st=S[q];st!==null&&(S[q]=null,y[q].disconnect(st))}N=null,U=null,m.reset();for(let q in x)delete x[q];if(t.setRenderTarget(w),f=null,d=null,u=null,a=null,p=null,Ct.stop(),n.isPresenting=!1,t.setPixelRatio(M),t.setSize(g.width,g.height,!1),E!==null){let q=E.camera;q.fov=E.fov,q.zoom=E.zoom,q.updateProjectionMatrix(),E=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(q){s=q,n.isPresenting===!0&&Dt("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(q){o=q,n.isPresenting===!0&&Dt("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||r},this.setReferenceSpace=function(q){l=q},this.getBaseLayer=function(){return d!==null?d:f},this.getBinding=function(){return u===null&&_&&(u=new XRWebGLBinding(a,e)),u},this.getFrame=function(){return b},this.getSession=function(){return a},this.setSession=async function(q){if(a=q,a!==null){if(w=t.getRenderTarget(),a.addEventListener("select",z),a.addEventListener("selectstart",z),a.addEventListener("selectend",z),a.addEventListener("squeeze",z),a.addEventListener("squeezestart",z),a.addEventListener("squeezeend",z),a.addEventListener("end",F),a.addEventListener("inputsourceschange",K),v.xrCompatible!==!0&&await e.makeXRCompatible(),M=t.getPixelRatio(),t.getSize(g),_&&"createProjectionLayer"in XRWebGLBinding.prototype){let xt=null,It=null,mt=null;v.depth&&(mt=v.stencil?e.DEPTH24_STENCIL8:e.DEPTH_COMPONENT24,xt=v.stencil?Ni:Ei,It=v.stencil?_a:wn);let Ot={colorFormat:e.RGBA8,depthFormat:mt,scaleFactor:s};u=this.getBinding(),d=u.createProjectionLayer(Ot),a.updateRenderState({layers:[d]}),t.setPixelRatio(1),t.setSize(d.textureWidth,d.textureHeight,!1),p=new Cn(d.textureWidth,d.textureHeight,{format:xn,type:sn,depthTexture:new Ri(d.textureWidth,d.textureHeight,It,void 0,void 0,void 0,void 0,void 0,void 0,xt),stencilBuffer:v.stencil,colorSpace:t.outputColorSpace,samples:v.antialias?4:0,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}else{let xt={antialias:v.antialias,alpha:!0,depth:v.depth,stencil:v.stencil,framebufferScaleFactor:s};f=new XRWebGLLayer(a,e,xt),a.updateRenderState({baseLayer:f}),t.setPixelRatio(1),t.setSize(f.framebufferWidth,f.framebufferHeight,!1),p=new Cn(f.framebufferWidth,f.framebufferHeight,{format:xn,type:sn,colorSpace:t.outputColorSpace,stencilBuffer:v.stencil,resolveDepthBuffer:f.ignoreDepthValues===!1,resolveStencilBuffer:f.ignoreDepthValues===!1,storeMultisampledDepthBuffer:f.ignoreDepthValues===!1,storeMultisampledStencilBuffer:f.ignoreDepthValues===!1})}p.isXRRenderTarget=!0,this.setFoveation(c),l=null,r=await a.requestReferenceSpace(o),Ct.setContext(a),Ct.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(a!==null)return a.environmentBlendMode},this.getDepthTexture=function(){return m.getDepthTexture()};function K(q){for(let st=0;st<q.removed.length;st++){let xt=q.removed[st],It=S.indexOf(xt);It>=0&&(S[It]=null,y[It].disconnect(xt))}for(let st=0;st<q.added.length;st++){let xt=q.added[st],It=S.indexOf(xt);if(It===-1){for(let Ot=0;Ot<y.length;Ot++)if(Ot>=S.length){S.push(xt),It=Ot;break}else if(S[Ot]===null){S[Ot]=xt,It=Ot;break}if(It===-1)break}let mt=y[It];mt&&mt.connect(xt)}}function H(q,st){st===null?q.matrixWorld.copy(q.matrix):q.matrixWorld.multiplyMatrices(st.matrixWorld,q.matrix),q.matrixWorldInverse.copy(q.matrixWorld).invert()}this.updateCamera=function(q){if(a===null)return;let st=q.near,xt=q.far;m.texture!==null&&(m.depthNear>0&&(st=m.depthNear),m.depthFar>0&&(xt=m.depthFar)),P.near=I.near=A.near=st,P.far=I.far=A.far=xt,(N!==P.near||U!==P.far)&&(a.updateRenderState({depthNear:P.near,depthFar:P.far}),N=P.near,U=P.far),P.layers.mask=q.layers.mask|6,A.layers.mask=P.layers.mask&-5,I.layers.mask=P.layers.mask&-3;let It=q.parent,mt=P.cameras;H(P,It);for(let Ot=0;Ot<mt.length;Ot++)H(mt[Ot],It);P.projectionMatrix.copy(A.projectionMatrix),P.projectionMatrixInverse.copy(A.projectionMatrixInverse),E===null&&q.isPerspectiveCamera&&(E={camera:q,fov:q.fov,zoom:q.zoom}),J(q,P,It)};function J(q,st,xt){xt===null?q.matrix.copy(st.matrixWorld):(q.matrix.copy(xt.matrixWorld),q.matrix.invert(),q.matrix.multiply(st.matrixWorld)),q.matrix.decompose(q.position,q.quaternion,q.scale),q.updateMatrixWorld(!0),q.projectionMatrix.copy(st.projectionMatrix),q.projectionMatrixInverse.copy(st.projectionMatrixInverse),q.isPerspectiveCamera&&(q.fov=Ja*2*Math.atan(1/q.projectionMatrix.elements[5]),q.zoom=1)}this.getCamera=function(){return P},this.getFoveation=function(){if(!(d===null&&f===null))return c},this.setFoveation=function(q){c=q,d!==null&&(d.fixedFoveation=q),f!==null&&f.fixedFoveation!==void 0&&(f.fixedFoveation=q)},this.hasDepthSensing=function(){return m.texture!==null},this.getDepthSensingMesh=function(){return m.getMesh(P)},this.getCameraTexture=function(q){return x[q]};let tt=null;function ft(q,st){if(h=st.getViewerPose(l||r),b=st,h!==null){let xt=h.views;f!==null&&(t.setRenderTargetFramebuffer(p,f.framebuffer),t.setRenderTarget(p));let It=!1;xt.length!==P.cameras.length&&(P.cameras.length=0,It=!0);for(let Lt=0;Lt<xt.length;Lt++){let $t=xt[Lt],Yt=null;if(f!==null)Yt=f.getViewport($t);else{let De=u.getViewSubImage(d,$t);Yt=De.viewport,Lt===0&&(t.setRenderTargetTextures(p,De.colorTexture,De.depthStencilTexture),t.setRenderTarget(p))}let qt=C[Lt];qt===void 0&&(qt=new pn,qt.layers.enable(Lt),qt.viewport=new re,C[Lt]=qt),qt.matrix.fromArray($t.transform.matrix),qt.matrix.decompose(qt.position,qt.quaternion,qt.scale),qt.projectionMatrix.fromArray($t.projectionMatrix),qt.projectionMatrixInverse.copy(qt.projectionMatrix).invert(),qt.viewport.set(Yt.x,Yt.y,Yt.width,Yt.height),Lt===0&&(P.matrix.copy(qt.matrix),P.matrix.decompose(P.position,P.quaternion,P.scale)),It===!0&&P.cameras.push(qt)}let mt=a.enabledFeatures;if(mt&&mt.includes("depth-sensing")&&a.depthUsage=="gpu-optimized"&&_){u=n.getBinding();let Lt=u.getDepthInformation(xt[0]);Lt&&Lt.isValid&&Lt.texture&&m.init(Lt,a.renderState)}if(mt&&mt.includes("camera-access")&&_){t.state.unbindTexture(),u=n.getBinding();for(let Lt=0;Lt<xt.length;Lt++){let $t=xt[Lt].camera;if($t){let Yt=x[$t];Yt||(Yt=new cr,x[$t]=Yt);let qt=u.getCameraImage($t);Yt.sourceTexture=qt}}}}for(let xt=0;xt<y.length;xt++){let It=S[xt],mt=y[xt];It!==null&&mt!==void 0&&mt.update(It,st,l||r)}tt&&tt(q,st),st.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:st}),b=null}let Ct=new bp;Ct.setAnimationLoop(ft),this.setAnimationLoop=function(q){tt=q},this.dispose=function(){}}},Cv=new se,Tp=new Bt;Tp.set(-1,0,0,0,1,0,0,0,1);Lv=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),hi=null;il=class{constructor(t={}){let{canvas:e=Gf(),context:n=null,depth:a=!0,stencil:s=!1,alpha:r=!1,antialias:o=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:d=!1,outputBufferType:f=sn}=t;this.isWebGLRenderer=!0;let b;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");b=n.getContextAttributes().alpha}else b=r;let _=f,m=new Set([hs,ls,va]),x=new Set([sn,wn,Yi,_a,_c,vc]),v=new Uint32Array(4),w=new Int32Array(4),p={textures:[],min:[],max:[],resolution:[]},y=null,S=null,g=[],M=[],E=null;this.domElement=e,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ci,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let A=this,I=!1,C=null,P=null,N=null,U=null;this._outputColorSpace=In;let z=0,F=0,K=null,H=-1,J=null,tt=new re,ft=new re,Ct=null,q=new Ht(0),st=0,xt=e.width,It=e.height,mt=1,Ot=null,Me=null,Lt=new re(0,0,xt,It),$t=new re(0,0,xt,It),Yt=!1,qt=new Ii,De=new nr,et=!1,vt=!1,At=new se,ne=new k,Vt=new re,Se={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},xe=!1;function ge(){return K===null?mt:1}let B=n;function Te(R,O){return e.getContext(R,O)}let ie,te,lt,de,Et,Nt,L,T,V,at,$,rt,dt,Z,j,ut,D,Q,Y,nt,ot,ht,Rt;try{let R={alpha:!0,depth:a,stencil:s,antialias:o,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:h,failIfMajorPerformanceCaveat:u};if("setAttribute"in e&&e.setAttribute("data-engine",`three.js r${"187"}`),e.addEventListener("webglcontextlost",Pt,!1),e.addEventListener("webglcontextrestored",Gt,!1),e.addEventListener("webglcontextcreationerror",yt,!1),B===null){let O="webgl2";if(B=Te(O,R),B===null)throw Te(O)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Wt()}catch(R){throw e.removeEventListener("webglcontextlost",Pt,!1),e.removeEventListener("webglcontextrestored",Gt,!1),e.removeEventListener("webglcontextcreationerror",yt,!1),Ft("WebGLRenderer: "+R.message),R}function Wt(){ie=new jy(B),ie.init(),ot=new Tv(B,ie),te=new Dy(B,ie,t,ot),lt=new Av(B,ie),te.reversedDepthBuffer&&d&&lt.buffers.depth.setReversed(!0),P=B.createFramebuffer(),N=B.createFramebuffer(),U=B.createFramebuffer(),de=new Yy(B),Et=new dv,Nt=new Ev(B,ie,lt,Et,te,ot,de),L=new Wy(A),T=new Kb(B),ht=new Py(B,T),V=new Xy(B,T,de,ht),at=new Ky(B,V,T,ht,de),Q=new Jy(B,te,Nt),j=new Uy(Et),$=new hv(A,L,ie,te,ht,j),rt=new Nv(A,Et),dt=new fv,Z=new yv(ie),D=new Ny(A,L,lt,at,b,c),ut=new wv(A,at,te),Rt=new Pv(B,de,te,lt),Y=new Ly(B,ie,de),nt=new qy(B,ie,de),de.programs=$.programs,A.capabilities=te,A.extensions=ie,A.properties=Et,A.renderLists=dt,A.shadowMap=ut,A.state=lt,A.info=de}_!==sn&&(E=new Qy(_,e.width,e.height,o,a,s));let ct=new Ad(A,B);this.xr=ct,this.getContext=function(){return B},this.getContextAttributes=function(){return B.getContextAttributes()},this.forceContextLoss=function(){let R=ie.get("WEBGL_lose_context");R&&R.loseContext()},this.forceContextRestore=function(){let R=ie.get("WEBGL_lose_context");R&&R.restoreContext()},this.getPixelRatio=function(){return mt},this.setPixelRatio=function(R){R!==void 0&&(mt=R,this.setSize(xt,It,!1))},this.getSize=function(R){return R.set(xt,It)},this.setSize=function(R,O,X=!0){if(ct.isPresenting){Dt("WebGLRenderer: Can't change size while VR device is presenting.");return}xt=R,It=O,e.width=Math.floor(R*mt),e.height=Math.floor(O*mt),X===!0&&(e.style.width=R+"px",e.style.height=O+"px"),E!==null&&E.setSize(e.width,e.height),this.setViewport(0,0,R,O)},this.getDrawingBufferSize=function(R){return R.set(xt*mt,It*mt).floor()},this.setDrawingBufferSize=function(R,O,X){xt=R,It=O,mt=X,e.width=Math.floor(R*X),e.height=Math.floor(O*X),this.setViewport(0,0,R,O)},this.setEffects=function(R){if(_===sn){Ft("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(R){for(let O=0;O<R.length;O++)if(R[O].isOutputPass===!0){Dt("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}E.setEffects(R||[])},this.getCurrentViewport=function(R){return R.copy(tt)},this.getViewport=function(R){return R.copy(Lt)},this.setViewport=function(R,O,X,G){R.isVector4?Lt.set(R.x,R.y,R.z,R.w):Lt.set(R,O,X,G),lt.viewport(tt.copy(Lt).multiplyScalar(ge()).round())},this.getScissor=function(R){return R.copy($t)},this.setScissor=function(R,O,X,G){R.isVector4?$t.set(R.x,R.y,R.z,R.w):$t.set(R,O,X,G),lt.scissor(ft.copy($t).multiplyScalar(ge()).round())},this.getScissorTest=function(){return Yt},this.setScissorTest=function(R){lt.setScissorTest(Yt=R)},this.setOpaqueSort=function(R){Ot=R},this.setTransparentSort=function(R){Me=R},this.getClearColor=function(R){return R.copy(D.getClearColor())},this.setClearColor=function(){D.setClearColor(...arguments)},this.getClearAlpha=function(){return D.getClearAlpha()},this.setClearAlpha=function(){D.setClearAlpha(...arguments)},this.clear=function(R=!0,O=!0,X=!0){let G=0;if(R){let W=!1;if(K!==null){let gt=K.texture.format;W=m.has(gt)}if(W){let gt=K.texture.type,Mt=x.has(gt),pt=D.getClearColor(),_t=D.getClearAlpha(),Tt=pt.r,kt=pt.g,Zt=pt.b;Mt?(v[0]=Tt,v[1]=kt,v[2]=Zt,v[3]=_t,B.clearBufferuiv(B.COLOR,0,v)):(w[0]=Tt,w[1]=kt,w[2]=Zt,w[3]=_t,B.clearBufferiv(B.COLOR,0,w))}else G|=B.COLOR_BUFFER_BIT}O&&(G|=B.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),X&&(G|=B.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),G!==0&&B.clear(G)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(R){R.setRenderer(this),C=R},this.dispose=function(){e.removeEventListener("webglcontextlost",Pt,!1),e.removeEventListener("webglcontextrestored",Gt,!1),e.removeEventListener("webglcontextcreationerror",yt,!1),D.dispose(),dt.dispose(),Z.dispose(),Nt.dispose(),Et.dispose(),L.dispose(),at.dispose(),V.dispose(),ht.dispose(),Rt.dispose(),$.dispose(),ct.dispose(),ct.removeEventListener("sessionstart",gu),ct.removeEventListener("sessionend",bu),sa.stop()};function Pt(R){R.preventDefault(),Zs("WebGLRenderer: Context Lost."),I=!0}function Gt(){Zs("WebGLRenderer: Context Restored."),I=!1;let R=de.autoReset,O=ut.enabled,X=ut.autoUpdate,G=ut.needsUpdate,W=ut.type;Wt(),de.autoReset=R,ut.enabled=O,ut.autoUpdate=X,ut.needsUpdate=G,ut.type=W}function yt(R){Ft("WebGLRenderer: A WebGL context could not be created. Reason: ",R.statusMessage)}function pe(R){let O=R.target;O.removeEventListener("dispose",pe),Ve(O)}function Ve(R){Oi(R),Et.remove(R)}function Oi(R){let O=Et.get(R).programs;O!==void 0&&(O.forEach(function(X){$.releaseProgram(X)}),R.isShaderMaterial&&$.releaseShaderCache(R))}this.renderBufferDirect=function(R,O,X,G,W,gt){O===null&&(O=Se);let Mt=W.isMesh&&W.matrixWorld.determinantAffine()<0,pt=kg(R,O,X,G,W);lt.setMaterial(G,Mt);let _t=X.index,Tt=1;if(G.wireframe===!0){if(_t=V.getWireframeAttribute(X),_t===void 0)return;Tt=2}let kt=X.drawRange,Zt=X.attributes.position,St=kt.start*Tt,Qt=(kt.start+kt.count)*Tt;gt!==null&&(St=Math.max(St,gt.start*Tt),Qt=Math.min(Qt,(gt.start+gt.count)*Tt)),_t!==null?(St=Math.max(St,0),Qt=Math.min(Qt,_t.count)):Zt!=null&&(St=Math.max(St,0),Qt=Math.min(Qt,Zt.count));let Ce=Qt-St;if(Ce<0||Ce===1/0)return;ht.setup(W,G,pt,X,_t);let we,ye=Y;if(_t!==null&&(we=T.get(_t),ye=nt,ye.setIndex(we)),W.isMesh)G.wireframe===!0?(lt.setLineWidth(G.wireframeLinewidth*ge()),ye.setMode(B.LINES)):ye.setMode(B.TRIANGLES);else if(W.isLine){let Qe=G.linewidth;Qe===void 0&&(Qe=1),lt.setLineWidth(Qe*ge()),W.isLineSegments?ye.setMode(B.LINES):W.isLineLoop?ye.setMode(B.LINE_LOOP):ye.setMode(B.LINE_STRIP)}else W.isPoints?ye.setMode(B.POINTS):W.isSprite&&ye.setMode(B.TRIANGLES);if(W.isBatchedMesh)if(ie.get("WEBGL_multi_draw"))ye.renderMultiDraw(W._multiDrawStarts,W._multiDrawCounts,W._multiDrawCount);else{let Qe=W._multiDrawStarts,wt=W._multiDrawCounts,dn=W._multiDrawCount,oe=_t?T.get(_t).bytesPerElement:1,ra=Et.get(G).currentProgram.getUniforms();for(let $e=0;$e<dn;$e++)ra.setValue(B,"_gl_DrawID",$e),ye.render(Qe[$e]/oe,wt[$e])}else if(W.isInstancedMesh)ye.renderInstances(St,Ce,W.count);else if(X.isInstancedBufferGeometry){let Qe=X._maxInstanceCount!==void 0?X._maxInstanceCount:1/0,wt=Math.min(X.instanceCount,Qe);ye.renderInstances(St,Ce,wt)}else ye.render(St,Ce)};function mu(R,O,X,G){C!==null&&R.isNodeMaterial&&C.setObject(G,R),et===!0&&j.setState(R,X,!1),R.transparent===!0&&R.side===Bn&&R.forceSinglePass===!1?(R.side=Xe,R.needsUpdate=!0,Bs(R,O,G),R.side=oi,R.needsUpdate=!0,Bs(R,O,G),R.side=Bn):Bs(R,O,G)}this.compile=function(R,O,X=null){X===null&&(X=R),C!==null&&C.renderStart(R,O,X),S=Z.get(X),S.init(O),M.push(S),X.traverseVisible(function(W){W.isLight&&W.layers.test(O.layers)&&(S.pushLight(W),W.castShadow&&S.pushShadow(W))}),R!==X&&R.traverseVisible(function(W){W.isLight&&W.layers.test(O.layers)&&(S.pushLight(W),W.castShadow&&S.pushShadow(W))}),S.setupLights(),C!==null&&C.updateLights(S.state.lightsArray),vt=this.localClippingEnabled,et=j.init(this.clippingPlanes,vt),et===!0&&j.setGlobalState(this.clippingPlanes,O),C!==null&&ut.render(S.state.shadowsArray,X,O);let G=new Set;return R.traverse(function(W){if(!(W.isMesh||W.isPoints||W.isLine||W.isSprite))return;let gt=W.material;if(gt)if(Array.isArray(gt))for(let Mt=0;Mt<gt.length;Mt++){let pt=gt[Mt];mu(pt,X,O,W),G.add(pt)}else mu(gt,X,O,W),G.add(gt)}),S=M.pop(),C!==null&&C.renderEnd(),G},this.compileAsync=function(R,O,X=null){let G=this.compile(R,O,X);return new Promise(W=>{function gt(){if(G.forEach(function(Mt){let _t=Et.get(Mt).currentProgram;(_t===void 0||_t.isReady())&&G.delete(Mt)}),G.size===0){W(R);return}setTimeout(gt,10)}ie.get("KHR_parallel_shader_compile")!==null?gt():setTimeout(gt,10)})};let Jl=null;function Fg(R){Jl&&Jl(R)}function gu(){sa.stop()}function bu(){sa.start()}let sa=new bp;sa.setAnimationLoop(Fg),typeof self<"u"&&sa.setContext(self),this.setAnimationLoop=function(R){Jl=R,ct.setAnimationLoop(R),R===null?sa.stop():sa.start()},ct.addEventListener("sessionstart",gu),ct.addEventListener("sessionend",bu),this.render=function(R,O){if(O!==void 0&&O.isCamera!==!0){Ft("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(I===!0)return;C!==null&&C.renderStart(R,O);let X=ct.enabled===!0&&ct.isPresenting===!0,G=E!==null&&(K===null||X)&&E.begin(A,K);if(R.matrixWorldAutoUpdate===!0&&R.updateMatrixWorld(),O.parent===null&&O.matrixWorldAutoUpdate===!0&&O.updateMatrixWorld(),ct.enabled===!0&&ct.isPresenting===!0&&(E===null||E.isCompositing()===!1)&&(ct.cameraAutoUpdate===!0&&ct.updateCamera(O),O=ct.getCamera()),R.isScene===!0&&R.onBeforeRender(A,R,O,K),S=Z.get(R,M.length),S.init(O),S.state.textureUnits=Nt.getTextureUnits(),M.push(S),At.multiplyMatrices(O.projectionMatrix,O.matrixWorldInverse),O.isArrayCamera?De.setFromArrayCamera(O):qt.setFromProjectionMatrix(At,On,O.reversedDepth),vt=this.localClippingEnabled,et=j.init(this.clippingPlanes,vt),y=dt.get(R,g.length),y.init(),g.push(y),this.info.render.frame++,ct.enabled===!0&&ct.isPresenting===!0){let Mt=A.xr.getDepthSensingMesh();Mt!==null&&Kl(Mt,O,-1/0,A.sortObjects)}Kl(R,O,0,A.sortObjects),y.finish(),C!==null&&C.updateLights(S.state.lightsArray),A.sortObjects===!0&&y.sort(Ot,Me),xe=ct.enabled===!1||ct.isPresenting===!1||ct.hasDepthSensing()===!1,xe&&D.addToRenderList(y,R),this.info.autoReset===!0&&this.info.reset(),et===!0&&j.beginShadows();let W=S.state.shadowsArray;if(ut.render(W,R,O),et===!0&&j.endShadows(),(G&&E.hasRenderPass())===!1){let Mt=y.opaque,pt=y.transmissive;if(S.setupLights(),O.isArrayCamera){let _t=O.cameras;if(pt.length>0)for(let Tt=0,kt=_t.length;Tt<kt;Tt++){let Zt=_t[Tt];yu(Mt,pt,R,Zt)}xe&&D.render(R);for(let Tt=0,kt=_t.length;Tt<kt;Tt++){let Zt=_t[Tt];xu(y,R,Zt,Zt.viewport)}}else pt.length>0&&yu(Mt,pt,R,O),xe&&D.render(R),xu(y,R,O)}K!==null&&F===0&&(Nt.updateMultisampleRenderTarget(K),Nt.updateRenderTargetMipmap(K)),G&&E.end(A),R.isScene===!0&&R.onAfterRender(A,R,O),ht.resetDefaultState(),H=-1,J=null,M.pop(),M.length>0?(S=M[M.length-1],Nt.setTextureUnits(S.state.textureUnits),et===!0&&j.setGlobalState(A.clippingPlanes,S.state.camera)):S=null,g.pop(),g.length>0?y=g[g.length-1]:y=null,C!==null&&C.renderEnd()};function Kl(R,O,X,G){if(R.visible===!1)return;if(R.layers.test(O.layers)){if(R.isGroup)X=R.renderOrder;else if(R.isLOD)R.autoUpdate===!0&&R.update(O);else if(R.isLight)S.pushLight(R),R.castShadow&&S.pushShadow(R);else if(R.isSprite){let Mt=O.isArrayCamera?De:qt;if(!R.frustumCulled||R.intersectsFrustum(Mt)){G&&Vt.setFromMatrixPosition(R.matrixWorld).applyMatrix4(At);let pt=at.update(R),_t=R.material;_t.visible&&y.push(R,pt,_t,X,Vt.z,null,O)}}else if(R.isMesh||R.isLine||R.isPoints){let Mt=O.isArrayCamera?De:qt;if(!R.frustumCulled||R.intersectsFrustum(Mt)){let pt=at.update(R),_t=R.material;if(G&&(R.boundingSphere!==void 0?(R.boundingSphere===null&&R.computeBoundingSphere(),Vt.copy(R.boundingSphere.center)):(pt.boundingSphere===null&&pt.computeBoundingSphere(),Vt.copy(pt.boundingSphere.center)),Vt.applyMatrix4(R.matrixWorld).applyMatrix4(At)),Array.isArray(_t)){let Tt=pt.groups;for(let kt=0,Zt=Tt.length;kt<Zt;kt++){let St=Tt[kt],Qt=_t[St.materialIndex];Qt&&Qt.visible&&y.push(R,pt,Qt,X,Vt.z,St,O)}}else _t.visible&&y.push(R,pt,_t,X,Vt.z,null,O)}}}let gt=R.children;for(let Mt=0,pt=gt.length;Mt<pt;Mt++)Kl(gt[Mt],O,X,G)}function xu(R,O,X,G){let{opaque:W,transmissive:gt,transparent:Mt}=R;S.setupLightsView(X),et===!0&&j.setGlobalState(A.clippingPlanes,X),G&&lt.viewport(tt.copy(G)),W.length>0&&ao(W,O,X),gt.length>0&&ao(gt,O,X),Mt.length>0&&ao(Mt,O,X),lt.buffers.depth.setTest(!0),lt.buffers.depth.setMask(!0),lt.buffers.color.setMask(!0),lt.setPolygonOffset(!1)}function yu(R,O,X,G){if((X.isScene===!0?X.overrideMaterial:null)!==null)return;if(S.state.transmissionRenderTarget[G.id]===void 0){let St=ie.has("EXT_color_buffer_half_float")||ie.has("EXT_color_buffer_float");S.state.transmissionRenderTarget[G.id]=new Cn(1,1,{generateMipmaps:!0,type:St?Kn:sn,minFilter:Ci,samples:Math.max(4,te.samples),stencilBuffer:s,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:Jt.workingColorSpace})}let gt=S.state.transmissionRenderTarget[G.id],Mt=G.viewport||tt;gt.setSize(Mt.z*A.transmissionResolutionScale,Mt.w*A.transmissionResolutionScale);let pt=A.getRenderTarget(),_t=A.getActiveCubeFace(),Tt=A.getActiveMipmapLevel();A.setRenderTarget(gt),A.getClearColor(q),st=A.getClearAlpha(),st<1&&A.setClearColor(16777215,.5),A.clear(),xe&&D.render(X);let kt=A.toneMapping;A.toneMapping=ci;let Zt=G.viewport;if(G.viewport!==void 0&&(G.viewport=void 0),S.setupLightsView(G),et===!0&&j.setGlobalState(A.clippingPlanes,G),ao(R,X,G),Nt.updateMultisampleRenderTarget(gt),Nt.updateRenderTargetMipmap(gt),ie.has("WEBGL_multisampled_render_to_texture")===!1){let St=!1;for(let Qt=0,Ce=O.length;Qt<Ce;Qt++){let we=O[Qt],{object:ye,geometry:Qe,material:wt,group:dn}=we;if(wt.side===Bn&&ye.layers.test(G.layers)){let oe=wt.side;wt.side=Xe,wt.needsUpdate=!0,_u(ye,X,G,Qe,wt,dn),wt.side=oe,wt.needsUpdate=!0,St=!0}}St===!0&&(Nt.updateMultisampleRenderTarget(gt),Nt.updateRenderTargetMipmap(gt))}A.setRenderTarget(pt,_t,Tt),A.setClearColor(q,st),Zt!==void 0&&(G.viewport=Zt),A.toneMapping=kt}function ao(R,O,X){let G=O.isScene===!0?O.overrideMaterial:null;for(let W=0,gt=R.length;W<gt;W++){let Mt=R[W],{object:pt,geometry:_t,group:Tt}=Mt,kt=Mt.material;kt.allowOverride===!0&&G!==null&&(kt=G),pt.layers.test(X.layers)&&_u(pt,O,X,_t,kt,Tt)}}function _u(R,O,X,G,W,gt){C!==null&&W.isNodeMaterial&&C.setObject(R,W),R.onBeforeRender(A,O,X,G,W,gt),R.modelViewMatrix.multiplyMatrices(X.matrixWorldInverse,R.matrixWorld),R.normalMatrix.getNormalMatrix(R.modelViewMatrix),W.onBeforeRender(A,O,X,G,R,gt),W.transparent===!0&&W.side===Bn&&W.forceSinglePass===!1?(W.side=Xe,W.needsUpdate=!0,A.renderBufferDirect(X,O,G,W,R,gt),W.side=oi,W.needsUpdate=!0,A.renderBufferDirect(X,O,G,W,R,gt),W.side=Bn):A.renderBufferDirect(X,O,G,W,R,gt),R.onAfterRender(A,O,X,G,W,gt)}function vu(R){let O=0;for(let X of R)X.texture!==null&&O++;return O}function Bs(R,O,X){O.isScene!==!0&&(O=Se);let G=Et.get(R),W=S.state.lights,gt=S.state.shadowsArray,Mt=W.state.version,pt=$.getParameters(R,W.state,gt,O,X,S.state.lightProbeGridArray),_t=$.getProgramCacheKey(pt),Tt=G.programs;G.environment=R.isMeshStandardMaterial||R.isMeshLambertMaterial||R.isMeshPhongMaterial?O.environment:null,G.fog=O.fog;let kt=R.isMeshStandardMaterial||R.isMeshLambertMaterial&&!R.envMap||R.isMeshPhongMaterial&&!R.envMap;G.envMap=L.get(R.envMap||G.environment,kt),G.envMapRotation=G.environment!==null&&R.envMap===null?O.environmentRotation:R.envMapRotation,Tt===void 0&&(R.addEventListener("dispose",pe),Tt=new Map,G.programs=Tt,G.programVariants=new Map);let Zt=Tt.get(_t);if(Zt!==void 0){if(G.currentProgram===Zt&&G.lightsStateVersion===Mt)return Su(R,pt),Zt}else pt.uniforms=$.getUniforms(R),C!==null&&R.isNodeMaterial&&C.build(R,X,pt),R.onBeforeCompile(pt,A),Zt=$.acquireProgram(pt,_t),Tt.set(_t,Zt),G.uniforms=pt.uniforms;let St=G.uniforms;return(!R.isShaderMaterial&&!R.isRawShaderMaterial||R.clipping===!0)&&(St.clippingPlanes=j.uniform),Su(R,pt),G.needsLights=Vg(R),G.lightsStateVersion=Mt,G.needsLights&&(St.ambientLightColor.value=W.state.ambient,St.lightProbe.value=W.state.probe,St.sunLights.value=W.state.sun,St.sunLightShadows.value=W.state.sunShadow,St.directionalLights.value=W.state.directional,St.directionalLightShadows.value=W.state.directionalShadow,St.spotLights.value=W.state.spot,St.spotLightShadows.value=W.state.spotShadow,St.rectAreaLights.value=W.state.rectArea,St.ltc_1.value=W.state.rectAreaLTC1,St.ltc_2.value=W.state.rectAreaLTC2,St.pointLights.value=W.state.point,St.pointLightShadows.value=W.state.pointShadow,St.hemisphereLights.value=W.state.hemi,St.sunShadowMatrix.value=W.state.sunShadowMatrix,St.sunShadowCascade.value=W.state.sunShadowCascade,St.directionalShadowMatrix.value=W.state.directionalShadowMatrix,St.spotLightMatrix.value=W.state.spotLightMatrix,St.spotLightMap.value=W.state.spotLightMap,St.pointShadowMatrix.value=W.state.pointShadowMatrix),G.numLightProbeGrids=vu(S.state.lightProbeGridArray),G.currentProgram=Zt,G.uniformsList=null,Zt}function Bg(R,O,X,G,W){let gt=Et.get(R),Mt=gt.currentProgram.id+","+G+","+W,pt=gt.programVariants.get(Mt);return pt===void 0?(pt=Bs(R,O,X),gt.programVariants.set(Mt,pt)):(gt.currentProgram=pt,gt.uniformsList=null,gt.outputColorSpace=G,gt.toneMapping=W),pt}function Mu(R){if(R.uniformsList===null){let O=R.currentProgram.getUniforms();R.uniformsList=ds.seqWithValue(O.seq,R.uniforms)}return R.uniformsList}function Su(R,O){let X=Et.get(R);X.outputColorSpace=O.outputColorSpace,X.batching=O.batching,X.batchingColor=O.batchingColor,X.instancing=O.instancing,X.instancingColor=O.instancingColor,X.instancingMorph=O.instancingMorph,X.skinning=O.skinning,X.morphTargets=O.morphTargets,X.morphNormals=O.morphNormals,X.morphColors=O.morphColors,X.morphTargetsCount=O.morphTargetsCount,X.numClippingPlanes=O.numClippingPlanes,X.numIntersection=O.numClipIntersection,X.vertexAlphas=O.vertexAlphas,X.vertexTangents=O.vertexTangents,X.toneMapping=O.toneMapping}function kg(R,O,X,G,W){O.isScene!==!0&&(O=Se),Nt.resetTextureUnits();let gt=O.fog,Mt=G.isMeshStandardMaterial||G.isMeshLambertMaterial||G.isMeshPhongMaterial?O.environment:null,pt=K===null?A.outputColorSpace:K.isXRRenderTarget===!0?K.texture.colorSpace:Jt.workingColorSpace,_t=G.isMeshStandardMaterial||G.isMeshLambertMaterial&&!G.envMap||G.isMeshPhongMaterial&&!G.envMap,Tt=L.get(G.envMap||Mt,_t),kt=G.vertexColors===!0&&!!X.attributes.color&&X.attributes.color.itemSize===4,Zt=!!X.attributes.tangent&&(!!G.normalMap||G.anisotropy>0),St=!!X.morphAttributes.position,Qt=!!X.morphAttributes.normal,Ce=!!X.morphAttributes.color,we=ci;G.toneMapped&&(K===null||K.isXRRenderTarget===!0)&&(we=A.toneMapping);let ye=X.morphAttributes.position||X.morphAttributes.normal||X.morphAttributes.color,Qe=ye!==void 0?ye.length:0,wt=Et.get(G),dn=S.state.lights;if(et===!0&&(vt===!0||R!==J)){let Ee=R===J&&G.id===H;j.setState(G,R,Ee)}let oe=!1,ra=!1;G.version===wt.__version?wt.needsLights&&wt.lightsStateVersion!==dn.state.version||W.isBatchedMesh&&wt.batching===!1||!W.isBatchedMesh&&wt.batching===!0||W.isBatchedMesh&&wt.batchingColor===!0&&W._colorsTexture===null||W.isBatchedMesh&&wt.batchingColor===!1&&W._colorsTexture!==null||W.isInstancedMesh&&wt.instancing===!1||!W.isInstancedMesh&&wt.instancing===!0||W.isSkinnedMesh&&wt.skinning===!1||!W.isSkinnedMesh&&wt.skinning===!0||W.isInstancedMesh&&wt.instancingColor===!0&&W.instanceColor===null||W.isInstancedMesh&&wt.instancingColor===!1&&W.instanceColor!==null||W.isInstancedMesh&&wt.instancingMorph===!0&&W.morphTexture===null||W.isInstancedMesh&&wt.instancingMorph===!1&&W.morphTexture!==null||wt.envMap!==Tt||G.fog===!0&&wt.fog!==gt||wt.numClippingPlanes!==void 0&&(wt.numClippingPlanes!==j.numPlanes||wt.numIntersection!==j.numIntersection)||wt.vertexAlphas!==kt||wt.vertexTangents!==Zt||wt.morphTargets!==St||wt.morphNormals!==Qt||wt.morphColors!==Ce||wt.morphTargetsCount!==Qe||wt.numLightProbeGrids!==vu(S.state.lightProbeGridArray)?oe=!0:(wt.outputColorSpace!==pt||wt.toneMapping!==we)&&(ra=!0):(oe=!0,wt.__version=G.version);let $e=wt.currentProgram;(oe===!0||ra===!0)&&($e=ra===!0?Bg(G,O,W,pt,we):Bs(G,O,W),C&&G.isNodeMaterial&&C.onUpdateProgram(G,$e,wt));let so=!1,Fi=!1,oa=!1,ae=$e.getUniforms(),je=wt.uniforms;if(lt.useProgram($e.program)&&(so=!0,Fi=!0,oa=!0),G.id!==H&&(H=G.id,Fi=!0),so||J!==R){lt.buffers.depth.getReversed()&&R.reversedDepth!==!0&&(R._reversedDepth=!0,R.updateProjectionMatrix()),ae.setValue(B,"projectionMatrix",R.projectionMatrix),ae.setValue(B,"viewMatrix",R.matrixWorldInverse);let He=ae.map.cameraPosition;He!==void 0&&He.setValue(B,ne.setFromMatrixPosition(R.matrixWorld)),te.logarithmicDepthBuffer&&ae.setValue(B,"logDepthBufFC",2/(Math.log(R.far+1)/Math.LN2)),(G.isMeshPhongMaterial||G.isMeshToonMaterial||G.isMeshLambertMaterial||G.isMeshBasicMaterial||G.isMeshStandardMaterial||G.isShaderMaterial)&&ae.setValue(B,"isOrthographic",R.isOrthographicCamera===!0),J!==R&&(J=R,Fi=!0,oa=!0)}if(wt.needsLights&&(dn.state.sunShadowMap.length>0&&ae.setValue(B,"sunShadowMap",dn.state.sunShadowMap,Nt),dn.state.directionalShadowMap.length>0&&ae.setValue(B,"directionalShadowMap",dn.state.directionalShadowMap,Nt),dn.state.spotShadowMap.length>0&&ae.setValue(B,"spotShadowMap",dn.state.spotShadowMap,Nt),dn.state.pointShadowMap.length>0&&ae.setValue(B,"pointShadowMap",dn.state.pointShadowMap,Nt)),W.isSkinnedMesh){ae.setOptional(B,W,"bindMatrix"),ae.setOptional(B,W,"bindMatrixInverse");let Ee=W.skeleton;Ee&&(Ee.boneTexture===null&&Ee.computeBoneTexture(),ae.setValue(B,"boneTexture",Ee.boneTexture,Nt))}W.isBatchedMesh&&(ae.setOptional(B,W,"batchingTexture"),ae.setValue(B,"batchingTexture",W._matricesTexture,Nt),ae.setOptional(B,W,"batchingIdTexture"),ae.setValue(B,"batchingIdTexture",W._indirectTexture,Nt),ae.setOptional(B,W,"batchingColorTexture"),W._colorsTexture!==null&&ae.setValue(B,"batchingColorTexture",W._colorsTexture,Nt));let Gn=X.morphAttributes;if((Gn.position!==void 0||Gn.normal!==void 0||Gn.color!==void 0)&&Q.update(W,X,$e),(Fi||wt.receiveShadow!==W.receiveShadow)&&(wt.receiveShadow=W.receiveShadow,ae.setValue(B,"receiveShadow",W.receiveShadow)),(G.isMeshStandardMaterial||G.isMeshLambertMaterial||G.isMeshPhongMaterial)&&G.envMap===null&&O.environment!==null&&(je.envMapIntensity.value=O.environmentIntensity),je.dfgLUT!==void 0&&(je.dfgLUT.value=Dv()),Fi){if(ae.setValue(B,"toneMappingExposure",A.toneMappingExposure),wt.needsLights&&zg(je,oa),gt&&G.fog===!0&&rt.refreshFogUniforms(je,gt),rt.refreshMaterialUniforms(je,G,mt,It,S.state.transmissionRenderTarget[R.id]),wt.needsLights&&wt.numLightProbeGrids>0){let Ee=p,He=0;for(let bi of S.state.lightProbeGridArray)bi.texture!==null&&(Ee.textures[He]=bi.texture,Ee.min[He]=bi.boundingBox.min,Ee.max[He]=bi.boundingBox.max,Ee.resolution[He]=bi.resolution,He++);for(let bi in Ee)Ee[bi].length=He;je.probesSH.value=Ee.textures,je.probesMin.value=Ee.min,je.probesMax.value=Ee.max,je.probesResolution.value=Ee.resolution}ds.upload(B,Mu(wt),je,Nt)}if(G.isShaderMaterial&&G.uniformsNeedUpdate===!0&&(ds.upload(B,Mu(wt),je,Nt),G.uniformsNeedUpdate=!1),G.isSpriteMaterial&&ae.setValue(B,"center",W.center),ae.setValue(B,"modelViewMatrix",W.modelViewMatrix),ae.setValue(B,"normalMatrix",W.normalMatrix),ae.setValue(B,"modelMatrix",W.matrixWorld),G.uniformsGroups!==void 0){let Ee=G.uniformsGroups;for(let He=0,bi=Ee.length;He<bi;He++){let Au=Ee[He];Rt.update(Au,$e),Rt.bind(Au,$e)}}return $e}function zg(R,O){R.ambientLightColor.needsUpdate=O,R.lightProbe.needsUpdate=O,R.sunLights.needsUpdate=O,R.sunLightShadows.needsUpdate=O,R.directionalLights.needsUpdate=O,R.directionalLightShadows.needsUpdate=O,R.pointLights.needsUpdate=O,R.pointLightShadows.needsUpdate=O,R.spotLights.needsUpdate=O,R.spotLightShadows.needsUpdate=O,R.rectAreaLights.needsUpdate=O,R.hemisphereLights.needsUpdate=O}function Vg(R){return R.isMeshLambertMaterial||R.isMeshToonMaterial||R.isMeshPhongMaterial||R.isMeshStandardMaterial||R.isShadowMaterial||R.isShaderMaterial&&R.lights===!0}this.getActiveCubeFace=function(){return z},this.getActiveMipmapLevel=function(){return F},this.getRenderTarget=function(){return K},this.setRenderTargetTextures=function(R,O,X){let G=Et.get(R);G.__autoAllocateDepthBuffer=R.resolveDepthBuffer===!1,G.__autoAllocateDepthBuffer===!1&&(G.__useRenderToTexture=!1),Et.get(R.texture).__webglTexture=O,Et.get(R.depthTexture).__webglTexture=G.__autoAllocateDepthBuffer?void 0:X,G.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(R,O){let X=Et.get(R);X.__webglFramebuffer=O,X.__useDefaultFramebuffer=O===void 0},this.setRenderTarget=function(R,O=0,X=0){K=R,z=O,F=X;let G=null,W=!1,gt=!1;if(R){let pt=Et.get(R);if(pt.__useDefaultFramebuffer!==void 0){lt.bindFramebuffer(B.FRAMEBUFFER,pt.__webglFramebuffer),tt.copy(R.viewport),ft.copy(R.scissor),Ct=R.scissorTest,lt.viewport(tt),lt.scissor(ft),lt.setScissorTest(Ct),H=-1;return}else if(pt.__webglFramebuffer===void 0)Nt.setupRenderTarget(R);else if(pt.__hasExternalTextures)Nt.rebindTextures(R,Et.get(R.texture).__webglTexture,Et.get(R.depthTexture).__webglTexture);else if(R.depthBuffer){let kt=R.depthTexture;if(pt.__boundDepthTexture!==kt){if(kt!==null&&Et.has(kt)&&(R.width!==kt.image.width||R.height!==kt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Nt.setupDepthRenderbuffer(R)}}let _t=R.texture;(_t.isData3DTexture||_t.isDataArrayTexture||_t.isCompressedArrayTexture)&&(gt=!0);let Tt=Et.get(R).__webglFramebuffer;R.isWebGLCubeRenderTarget?(Array.isArray(Tt[O])?G=Tt[O][X]:G=Tt[O],W=!0):R.samples>0&&Nt.useMultisampledRTT(R)===!1?G=Et.get(R).__webglMultisampledFramebuffer:Array.isArray(Tt)?G=Tt[X]:G=Tt,tt.copy(R.viewport),ft.copy(R.scissor),Ct=R.scissorTest}else tt.copy(Lt).multiplyScalar(mt).floor(),ft.copy($t).multiplyScalar(mt).floor(),Ct=Yt;if(X!==0&&(G=P),lt.bindFramebuffer(B.FRAMEBUFFER,G)&&lt.drawBuffers(R,G),lt.viewport(tt),lt.scissor(ft),lt.setScissorTest(Ct),W){let pt=Et.get(R.texture);B.framebufferTexture2D(B.FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_CUBE_MAP_POSITIVE_X+O,pt.__webglTexture,X)}else if(gt){let pt=O;for(let _t=0;_t<R.textures.length;_t++){let Tt=Et.get(R.textures[_t]);B.framebufferTextureLayer(B.FRAMEBUFFER,B.COLOR_ATTACHMENT0+_t,Tt.__webglTexture,X,pt)}}else if(R!==null&&X!==0){let pt=Et.get(R.texture);B.framebufferTexture2D(B.FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_2D,pt.__webglTexture,X)}H=-1};function wu(R){let O=Et.get(R);return(O.__readFormat!==R.format||O.__readType!==R.type)&&(O.__readFormat=R.format,O.__readType=R.type,O.__formatReadable=te.textureFormatReadable(R.format),O.__typeReadable=te.textureTypeReadable(R.type)),O}this.readRenderTargetPixels=function(R,O,X,G,W,gt,Mt,pt=0){if(!(R&&R.isWebGLRenderTarget)){Ft("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let _t=Et.get(R).__webglFramebuffer;if(R.isWebGLCubeRenderTarget&&Mt!==void 0&&(_t=_t[Mt],Array.isArray(_t)&&(_t=_t[0])),_t){lt.bindFramebuffer(B.FRAMEBUFFER,_t);try{let Tt=R.textures[pt],kt=Tt.format,Zt=Tt.type;R.textures.length>1&&B.readBuffer(B.COLOR_ATTACHMENT0+pt);let St=wu(Tt);if(St.__formatReadable===!1){Ft("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(St.__typeReadable===!1){Ft("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}O>=0&&O<=R.width-G&&X>=0&&X<=R.height-W&&B.readPixels(O,X,G,W,ot.convert(kt),ot.convert(Zt),gt)}finally{let Tt=K!==null?Et.get(K).__webglFramebuffer:null;lt.bindFramebuffer(B.FRAMEBUFFER,Tt)}}},this.readRenderTargetPixelsAsync=async function(R,O,X,G,W,gt,Mt,pt=0){if(!(R&&R.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let _t=Et.get(R).__webglFramebuffer;if(R.isWebGLCubeRenderTarget&&Mt!==void 0&&(_t=_t[Mt],Array.isArray(_t)&&(_t=_t[0])),_t)if(O>=0&&O<=R.width-G&&X>=0&&X<=R.height-W){lt.bindFramebuffer(B.FRAMEBUFFER,_t);let Tt=R.textures[pt],kt=Tt.format,Zt=Tt.type;R.textures.length>1&&B.readBuffer(B.COLOR_ATTACHMENT0+pt);let St=wu(Tt);if(St.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(St.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let Qt=B.createBuffer();B.bindBuffer(B.PIXEL_PACK_BUFFER,Qt),B.bufferData(B.PIXEL_PACK_BUFFER,gt.byteLength,B.STREAM_READ),B.readPixels(O,X,G,W,ot.convert(kt),ot.convert(Zt),0),B.bindBuffer(B.PIXEL_PACK_BUFFER,null);let Ce=K!==null?Et.get(K).__webglFramebuffer:null;lt.bindFramebuffer(B.FRAMEBUFFER,Ce);let we=B.fenceSync(B.SYNC_GPU_COMMANDS_COMPLETE,0);return B.flush(),await jf(B,we,4),B.bindBuffer(B.PIXEL_PACK_BUFFER,Qt),B.getBufferSubData(B.PIXEL_PACK_BUFFER,0,gt),B.bindBuffer(B.PIXEL_PACK_BUFFER,null),B.deleteBuffer(Qt),B.deleteSync(we),gt}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(R,O=null,X=0){let G=Math.pow(2,-X),W=Math.floor(R.image.width*G),gt=Math.floor(R.image.height*G),Mt=O!==null?O.x:0,pt=O!==null?O.y:0;Nt.setTexture2D(R,0),B.copyTexSubImage2D(B.TEXTURE_2D,X,0,0,Mt,pt,W,gt),lt.unbindTexture()},this.copyTextureToTexture=function(R,O,X=null,G=null,W=0,gt=0){let Mt,pt,_t,Tt,kt,Zt,St,Qt,Ce,we=R.isCompressedTexture?R.mipmaps[gt]:R.image;if(X!==null)Mt=X.max.x-X.min.x,pt=X.max.y-X.min.y,_t=X.isBox3?X.max.z-X.min.z:1,Tt=X.min.x,kt=X.min.y,Zt=X.isBox3?X.min.z:0;else{let ae=Math.pow(2,-W);Mt=Math.floor(we.width*ae),pt=Math.floor(we.height*ae),R.isDataArrayTexture?_t=we.depth:R.isData3DTexture?_t=Math.floor(we.depth*ae):_t=1,Tt=0,kt=0,Zt=0}G!==null?(St=G.x,Qt=G.y,Ce=G.z):(St=0,Qt=0,Ce=0);let ye=ot.convert(O.format),Qe=ot.convert(O.type),wt;O.isData3DTexture?(Nt.setTexture3D(O,0),wt=B.TEXTURE_3D):O.isDataArrayTexture||O.isCompressedArrayTexture?(Nt.setTexture2DArray(O,0),wt=B.TEXTURE_2D_ARRAY):(Nt.setTexture2D(O,0),wt=B.TEXTURE_2D),lt.activeTexture(B.TEXTURE0),lt.pixelStorei(B.UNPACK_FLIP_Y_WEBGL,O.flipY),lt.pixelStorei(B.UNPACK_PREMULTIPLY_ALPHA_WEBGL,O.premultiplyAlpha),lt.pixelStorei(B.UNPACK_ALIGNMENT,O.unpackAlignment);let dn=lt.getParameter(B.UNPACK_ROW_LENGTH),oe=lt.getParameter(B.UNPACK_IMAGE_HEIGHT),ra=lt.getParameter(B.UNPACK_SKIP_PIXELS),$e=lt.getParameter(B.UNPACK_SKIP_ROWS),so=lt.getParameter(B.UNPACK_SKIP_IMAGES);lt.pixelStorei(B.UNPACK_ROW_LENGTH,we.width),lt.pixelStorei(B.UNPACK_IMAGE_HEIGHT,we.height),lt.pixelStorei(B.UNPACK_SKIP_PIXELS,Tt),lt.pixelStorei(B.UNPACK_SKIP_ROWS,kt),lt.pixelStorei(B.UNPACK_SKIP_IMAGES,Zt);let Fi=R.isDataArrayTexture||R.isData3DTexture,oa=O.isDataArrayTexture||O.isData3DTexture;if(R.isDepthTexture){let ae=Et.get(R),je=Et.get(O),Gn=Et.get(ae.__renderTarget),Ee=Et.get(je.__renderTarget);lt.bindFramebuffer(B.READ_FRAMEBUFFER,Gn.__webglFramebuffer),lt.bindFramebuffer(B.DRAW_FRAMEBUFFER,Ee.__webglFramebuffer);for(let He=0;He<_t;He++)Fi&&(B.framebufferTextureLayer(B.READ_FRAMEBUFFER,B.COLOR_ATTACHMENT0,Et.get(R).__webglTexture,W,Zt+He),B.framebufferTextureLayer(B.DRAW_FRAMEBUFFER,B.COLOR_ATTACHMENT0,Et.get(O).__webglTexture,gt,Ce+He)),B.blitFramebuffer(Tt,kt,Tt+Mt,kt+pt,St,Qt,St+Mt,Qt+pt,B.DEPTH_BUFFER_BIT,B.NEAREST);lt.bindFramebuffer(B.READ_FRAMEBUFFER,null),lt.bindFramebuffer(B.DRAW_FRAMEBUFFER,null)}else if(W!==0||R.isRenderTargetTexture||Et.has(R)){let ae=Et.get(R),je=Et.get(O);lt.bindFramebuffer(B.READ_FRAMEBUFFER,N),lt.bindFramebuffer(B.DRAW_FRAMEBUFFER,U);for(let Gn=0;Gn<_t;Gn++)Fi?B.framebufferTextureLayer(B.READ_FRAMEBUFFER,B.COLOR_ATTACHMENT0,ae.__webglTexture,W,Zt+Gn):B.framebufferTexture2D(B.READ_FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_2D,ae.__webglTexture,W),oa?B.framebufferTextureLayer(B.DRAW_FRAMEBUFFER,B.COLOR_ATTACHMENT0,je.__webglTexture,gt,Ce+Gn):B.framebufferTexture2D(B.DRAW_FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_2D,je.__webglTexture,gt),W!==0?B.blitFramebuffer(Tt,kt,Tt+Mt,kt+pt,St,Qt,St+Mt,Qt+pt,B.COLOR_BUFFER_BIT,B.NEAREST):oa?B.copyTexSubImage3D(wt,gt,St,Qt,Ce+Gn,Tt,kt,Mt,pt):B.copyTexSubImage2D(wt,gt,St,Qt,Tt,kt,Mt,pt);lt.bindFramebuffer(B.READ_FRAMEBUFFER,null),lt.bindFramebuffer(B.DRAW_FRAMEBUFFER,null)}else oa?R.isDataTexture||R.isData3DTexture?B.texSubImage3D(wt,gt,St,Qt,Ce,Mt,pt,_t,ye,Qe,we.data):O.isCompressedArrayTexture?B.compressedTexSubImage3D(wt,gt,St,Qt,Ce,Mt,pt,_t,ye,we.data):B.texSubImage3D(wt,gt,St,Qt,Ce,Mt,pt,_t,ye,Qe,we):R.isDataTexture?B.texSubImage2D(B.TEXTURE_2D,gt,St,Qt,Mt,pt,ye,Qe,we.data):R.isCompressedTexture?B.compressedTexSubImage2D(B.TEXTURE_2D,gt,St,Qt,we.width,we.height,ye,we.data):B.texSubImage2D(B.TEXTURE_2D,gt,St,Qt,Mt,pt,ye,Qe,we);lt.pixelStorei(B.UNPACK_ROW_LENGTH,dn),lt.pixelStorei(B.UNPACK_IMAGE_HEIGHT,oe),lt.pixelStorei(B.UNPACK_SKIP_PIXELS,ra),lt.pixelStorei(B.UNPACK_SKIP_ROWS,$e),lt.pixelStorei(B.UNPACK_SKIP_IMAGES,so),gt===0&&O.generateMipmaps===!0&&O.mipmapsAutoUpdate===!0&&B.generateMipmap(wt),lt.unbindTexture()},this.initRenderTarget=function(R){Et.get(R).__webglFramebuffer===void 0&&Nt.setupRenderTarget(R)},this.initTexture=function(R){R.isCubeTexture?Nt.setTextureCube(R,0):R.isData3DTexture?Nt.setTexture3D(R,0):R.isDataArrayTexture||R.isCompressedArrayTexture?Nt.setTexture2DArray(R,0):Nt.setTexture2D(R,0),lt.unbindTexture()},this.resetState=function(){z=0,F=0,K=null,lt.reset(),ht.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return On}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(t){this._outputColorSpace=t;let e=this.getContext();e.drawingBufferColorSpace=Jt._getDrawingBufferColorSpace(t),e.unpackColorSpace=Jt._getUnpackColorSpace()}}});function Ov(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function Fv(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function Bv(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(Cp),this.state=ce.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let t=this._pointers[0],e=this._pointerPositions[t];this._onTouchStart({pointerId:t,pageX:e.x,pageY:e.y});break}}function kv(i){let t;switch(i.button){case 0:t=this.mouseButtons.LEFT;break;case 1:t=this.mouseButtons.MIDDLE;break;case 2:t=this.mouseButtons.RIGHT;break;default:t=-1}switch(t){case qi.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=ce.DOLLY;break;case qi.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=ce.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=ce.ROTATE}break;case qi.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=ce.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=ce.PAN}break;default:this.state=ce.NONE}this.state!==ce.NONE&&this.dispatchEvent(Td)}function zv(i){switch(this.state){case ce.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case ce.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case ce.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function Vv(i){this.enabled===!1||this.enableZoom===!1||this.state!==ce.NONE||(i.preventDefault(),this.dispatchEvent(Td),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(Cp))}function Hv(i){this.enabled!==!1&&this._handleKeyDown(i)}function Gv(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case ri.ROTATE:if(this.enableRotate===!1){this.state=ce.NONE;break}this._handleTouchStartRotate(i),this.state=ce.TOUCH_ROTATE;break;case ri.PAN:if(this.enablePan===!1){this.state=ce.NONE;break}this._handleTouchStartPan(i),this.state=ce.TOUCH_PAN;break;default:this.state=ce.NONE}break;case 2:switch(this.touches.TWO){case ri.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=ce.TOUCH_DOLLY_PAN;break;case ri.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=ce.TOUCH_DOLLY_ROTATE;break;default:this.state=ce.NONE}break;default:this.state=ce.NONE}this.state!==ce.NONE&&this.dispatchEvent(Td)}function Wv(i){switch(this._trackPointer(i),this.state){case ce.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case ce.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case ce.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case ce.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=ce.NONE}}function jv(i){this.enabled!==!1&&i.preventDefault()}function Xv(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function qv(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var Ip,Td,Cp,rl,Rp,Uv,ke,An,ce,Ed,ol,Np=ca(()=>{fs();Ip={type:"change"},Td={type:"start"},Cp={type:"end"},rl=new Jn,Rp=new fn,Uv=Math.cos(70*Ma.DEG2RAD),ke=new k,An=2*Math.PI,ce={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Ed=1e-6,ol=class extends wr{constructor(t,e=null){super(t,e),this.state=ce.NONE,this.target=new k,this.cursor=new k,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:qi.ROTATE,MIDDLE:qi.DOLLY,RIGHT:qi.PAN},this.touches={ONE:ri.ROTATE,TWO:ri.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new k,this._lastQuaternion=new Rn,this._lastTargetPosition=new k,this._quat=new Rn().setFromUnitVectors(t.up,new k(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new as,this._sphericalDelta=new as,this._scale=1,this._panOffset=new k,this._rotateStart=new Ut,this._rotateEnd=new Ut,this._rotateDelta=new Ut,this._panStart=new Ut,this._panEnd=new Ut,this._panDelta=new Ut,this._dollyStart=new Ut,this._dollyEnd=new Ut,this._dollyDelta=new Ut,this._dollyDirection=new k,this._mouse=new Ut,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=Fv.bind(this),this._onPointerDown=Ov.bind(this),this._onPointerUp=Bv.bind(this),this._onContextMenu=jv.bind(this),this._onMouseWheel=Vv.bind(this),this._onKeyDown=Hv.bind(this),this._onTouchStart=Gv.bind(this),this._onTouchMove=Wv.bind(this),this._onMouseDown=kv.bind(this),this._onMouseMove=zv.bind(this),this._interceptControlDown=Xv.bind(this),this._interceptControlUp=qv.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(t){this._cursorStyle=t,t==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(t){super.connect(t),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=ce.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(t){t.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=t}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(Ip),this.update(),this.state=ce.NONE}pan(t,e){this._pan(t,e),this.update()}dollyIn(t){this._dollyIn(t),this.update()}dollyOut(t){this._dollyOut(t),this.update()}rotateLeft(t){this._rotateLeft(t),this.update()}rotateUp(t){this._rotateUp(t),this.update()}update(t=null){let e=this.object.position;ke.copy(e).sub(this.target),ke.applyQuaternion(this._quat),this._spherical.setFromVector3(ke),this.autoRotate&&this.state===ce.NONE&&this._rotateLeft(this._getAutoRotationAngle(t)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,a=this.maxAzimuthAngle;isFinite(n)&&isFinite(a)&&(n<-Math.PI?n+=An:n>Math.PI&&(n-=An),a<-Math.PI?a+=An:a>Math.PI&&(a-=An),n<=a?this._spherical.theta=Math.max(n,Math.min(a,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+a)/2?Math.max(n,this._spherical.theta):Math.min(a,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let s=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let r=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),s=r!=this._spherical.radius}if(ke.setFromSpherical(this._spherical),ke.applyQuaternion(this._quatInverse),e.copy(this.target).add(ke),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let r=null;if(this.object.isPerspectiveCamera){let o=ke.length();r=this._clampDistance(o*this._scale);let c=o-r;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),s=!!c}else if(this.object.isOrthographicCamera){let o=new k(this._mouse.x,this._mouse.y,0);o.unproject(this.object);let c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),s=c!==this.object.zoom;let l=new k(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(o),this.object.updateMatrixWorld(),r=ke.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;r!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(r).add(this.object.position):(rl.origin.copy(this.object.position),rl.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(rl.direction))<Uv?this.object.lookAt(this.target):(Rp.setFromNormalAndCoplanarPoint(this.object.up,this.target),rl.intersectPlane(Rp,this.target))))}else if(this.object.isOrthographicCamera){let r=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),r!==this.object.zoom&&(this.object.updateProjectionMatrix(),s=!0)}return this._scale=1,this._performCursorZoom=!1,s||this._lastPosition.distanceToSquared(this.object.position)>Ed||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Ed||this._lastTargetPosition.distanceToSquared(this.target)>Ed?(this.dispatchEvent(Ip),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(t){return t!==null?An/60*this.autoRotateSpeed*t:An/60/60*this.autoRotateSpeed}_getZoomScale(t){let e=Math.abs(t*.01);return Math.pow(.95,this.zoomSpeed*e)}_rotateLeft(t){this._sphericalDelta.theta-=t}_rotateUp(t){this._sphericalDelta.phi-=t}_panLeft(t,e){ke.setFromMatrixColumn(e,0),ke.multiplyScalar(-t),this._panOffset.add(ke)}_panUp(t,e){this.screenSpacePanning===!0?ke.setFromMatrixColumn(e,1):(ke.setFromMatrixColumn(e,0),ke.crossVectors(this.object.up,ke)),ke.multiplyScalar(t),this._panOffset.add(ke)}_pan(t,e){let n=this.domElement;if(this.object.isPerspectiveCamera){let a=this.object.position;ke.copy(a).sub(this.target);let s=ke.length();s*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*t*s/n.clientHeight,this.object.matrix),this._panUp(2*e*s/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(t*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(e*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(t,e){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let n=this.domElement.getBoundingClientRect(),a=t-n.left,s=e-n.top,r=n.width,o=n.height;this._mouse.x=a/r*2-1,this._mouse.y=-(s/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(t){return Math.max(this.minDistance,Math.min(this.maxDistance,t))}_handleMouseDownRotate(t){this._rotateStart.set(t.clientX,t.clientY)}_handleMouseDownDolly(t){this._updateZoomParameters(t.clientX,t.clientY),this._dollyStart.set(t.clientX,t.clientY)}_handleMouseDownPan(t){this._panStart.set(t.clientX,t.clientY)}_handleMouseMoveRotate(t){this._rotateEnd.set(t.clientX,t.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let e=this.domElement;this._rotateLeft(An*this._rotateDelta.x/e.clientHeight),this._rotateUp(An*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(t){this._dollyEnd.set(t.clientX,t.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(t){this._panEnd.set(t.clientX,t.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(t){this._updateZoomParameters(t.clientX,t.clientY),t.deltaY<0?this._dollyIn(this._getZoomScale(t.deltaY)):t.deltaY>0&&this._dollyOut(this._getZoomScale(t.deltaY)),this.update()}_handleKeyDown(t){let e=!1;switch(t.code){case this.keys.UP:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(An*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),e=!0;break;case this.keys.BOTTOM:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(-An*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),e=!0;break;case this.keys.LEFT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(An*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),e=!0;break;case this.keys.RIGHT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(-An*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),e=!0;break}e&&(t.preventDefault(),this.update())}_handleTouchStartRotate(t){if(this._pointers.length===1)this._rotateStart.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._rotateStart.set(n,a)}}_handleTouchStartPan(t){if(this._pointers.length===1)this._panStart.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._panStart.set(n,a)}}_handleTouchStartDolly(t){let e=this._getSecondPointerPosition(t),n=t.pageX-e.x,a=t.pageY-e.y,s=Math.sqrt(n*n+a*a);this._dollyStart.set(0,s)}_handleTouchStartDollyPan(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enablePan&&this._handleTouchStartPan(t)}_handleTouchStartDollyRotate(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enableRotate&&this._handleTouchStartRotate(t)}_handleTouchMoveRotate(t){if(this._pointers.length==1)this._rotateEnd.set(t.pageX,t.pageY);else{let n=this._getSecondPointerPosition(t),a=.5*(t.pageX+n.x),s=.5*(t.pageY+n.y);this._rotateEnd.set(a,s)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let e=this.domElement;this._rotateLeft(An*this._rotateDelta.x/e.clientHeight),this._rotateUp(An*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(t){if(this._pointers.length===1)this._panEnd.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._panEnd.set(n,a)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(t){let e=this._getSecondPointerPosition(t),n=t.pageX-e.x,a=t.pageY-e.y,s=Math.sqrt(n*n+a*a);this._dollyEnd.set(0,s),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let r=(t.pageX+e.x)*.5,o=(t.pageY+e.y)*.5;this._updateZoomParameters(r,o)}_handleTouchMoveDollyPan(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enablePan&&this._handleTouchMovePan(t)}_handleTouchMoveDollyRotate(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enableRotate&&this._handleTouchMoveRotate(t)}_addPointer(t){this._pointers.push(t.pointerId)}_removePointer(t){delete this._pointerPositions[t.pointerId];for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId){this._pointers.splice(e,1);return}}_isTrackingPointer(t){for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId)return!0;return!1}_trackPointer(t){let e=this._pointerPositions[t.pointerId];e===void 0&&(e=new Ut,this._pointerPositions[t.pointerId]=e),e.set(t.pageX,t.pageY)}_getSecondPointerPosition(t){let e=t.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[e]}_customWheelEvent(t){let e=t.deltaMode,n={clientX:t.clientX,clientY:t.clientY,deltaY:t.deltaY};switch(e){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return t.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}});var ps,Id=ca(()=>{fs();bt.line={worldUnits:{value:1},linewidth:{value:1},resolution:{value:new Ut},dashOffset:{value:0},dashScale:{value:1},dashSize:{value:1},gapSize:{value:1}};yn.line={uniforms:Or.merge([bt.common,bt.fog,bt.line]),vertexShader:`
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
		`};ps=class extends Fn{constructor(t){super({type:"LineMaterial",uniforms:Or.clone(yn.line.uniforms),vertexShader:yn.line.vertexShader,fragmentShader:yn.line.fragmentShader,clipping:!0}),this.isLineMaterial=!0,this.setValues(t)}get color(){return this.uniforms.diffuse.value}set color(t){this.uniforms.diffuse.value=t}get worldUnits(){return"WORLD_UNITS"in this.defines}set worldUnits(t){t===!0!==this.worldUnits&&(this.needsUpdate=!0),t===!0?this.defines.WORLD_UNITS="":delete this.defines.WORLD_UNITS}get linewidth(){return this.uniforms.linewidth.value}set linewidth(t){this.uniforms.linewidth&&(this.uniforms.linewidth.value=t)}get dashed(){return"USE_DASH"in this.defines}set dashed(t){t===!0!==this.dashed&&(this.needsUpdate=!0),t===!0?this.defines.USE_DASH="":delete this.defines.USE_DASH}get dashScale(){return this.uniforms.dashScale.value}set dashScale(t){this.uniforms.dashScale.value=t}get dashSize(){return this.uniforms.dashSize.value}set dashSize(t){this.uniforms.dashSize.value=t}get dashOffset(){return this.uniforms.dashOffset.value}set dashOffset(t){this.uniforms.dashOffset.value=t}get gapSize(){return this.uniforms.gapSize.value}set gapSize(t){this.uniforms.gapSize.value=t}get opacity(){return this.uniforms.opacity.value}set opacity(t){this.uniforms&&(this.uniforms.opacity.value=t)}get resolution(){return this.uniforms.resolution.value}set resolution(t){this.uniforms.resolution.value.copy(t)}get alphaToCoverage(){return"USE_ALPHA_TO_COVERAGE"in this.defines}set alphaToCoverage(t){this.defines&&(t===!0!==this.alphaToCoverage&&(this.needsUpdate=!0),t===!0?this.defines.USE_ALPHA_TO_COVERAGE="":delete this.defines.USE_ALPHA_TO_COVERAGE)}}});var Pp,cl,ms,Rd=ca(()=>{fs();Pp=new Ue,cl=new k,ms=class extends vr{constructor(){super(),this.isLineSegmentsGeometry=!0,this.type="LineSegmentsGeometry";let t=[-1,2,0,1,2,0,-1,1,0,1,1,0,-1,0,0,1,0,0,-1,-1,0,1,-1,0],e=[-1,2,1,2,-1,1,1,1,-1,-1,1,-1,-1,-2,1,-2],n=[0,2,1,2,3,1,2,4,3,4,5,3,4,6,5,6,7,5];this.setIndex(n),this.setAttribute("position",new me(t,3)),this.setAttribute("uv",new me(e,2))}applyMatrix4(t){let e=this.attributes.instanceStart,n=this.attributes.instanceEnd;return e!==void 0&&(e.applyMatrix4(t),n.applyMatrix4(t),e.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this}setPositions(t){let e;t instanceof Float32Array?e=t:Array.isArray(t)&&(e=new Float32Array(t));let n=new Xi(e,6,1);return this.setAttribute("instanceStart",new Yn(n,3,0)),this.setAttribute("instanceEnd",new Yn(n,3,3)),this.instanceCount=this.attributes.instanceStart.count,this.computeBoundingBox(),this.computeBoundingSphere(),this}setColors(t){let e;t instanceof Float32Array?e=t:Array.isArray(t)&&(e=new Float32Array(t));let n=new Xi(e,6,1);return this.setAttribute("instanceColorStart",new Yn(n,3,0)),this.setAttribute("instanceColorEnd",new Yn(n,3,3)),this}fromWireframeGeometry(t){return this.setPositions(t.attributes.position.array),this}fromEdgesGeometry(t){return this.setPositions(t.attributes.position.array),this}fromMesh(t){return this.fromWireframeGeometry(new fr(t.geometry)),this}fromLineSegments(t){let e=t.geometry;return this.setPositions(e.attributes.position.array),this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Ue);let t=this.attributes.instanceStart,e=this.attributes.instanceEnd;t!==void 0&&e!==void 0&&(this.boundingBox.setFromBufferAttribute(t),Pp.setFromBufferAttribute(e),this.boundingBox.union(Pp))}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new We),this.boundingBox===null&&this.computeBoundingBox();let t=this.attributes.instanceStart,e=this.attributes.instanceEnd;if(t!==void 0&&e!==void 0){let n=this.boundingSphere.center;this.boundingBox.getCenter(n);let a=0;for(let s=0,r=t.count;s<r;s++)cl.fromBufferAttribute(t,s),a=Math.max(a,n.distanceToSquared(cl)),cl.fromBufferAttribute(e,s),a=Math.max(a,n.distanceToSquared(cl));this.boundingSphere.radius=Math.sqrt(a),isNaN(this.boundingSphere.radius)&&console.error("THREE.LineSegmentsGeometry.computeBoundingSphere(): Computed radius is NaN. The instanced position data is likely to have NaN values.",this)}}toJSON(){}}});function Op(i,t,e){return ui.set(0,0,-t,1).applyMatrix4(i.projectionMatrix),ui.multiplyScalar(1/ui.w),ui.x=wa/e.width,ui.y=wa/e.height,ui.applyMatrix4(i.projectionMatrixInverse),ui.multiplyScalar(1/ui.w),Math.abs(Math.max(ui.x,ui.y))}function Yv(i,t){let e=i.matrixWorld,n=i.geometry,a=n.attributes.instanceStart,s=n.attributes.instanceEnd,r=Math.min(n.instanceCount,a.count);for(let o=0,c=r;o<c;o++){Je.start.fromBufferAttribute(a,o),Je.end.fromBufferAttribute(s,o),Je.applyMatrix4(e);let l=new k,h=new k;fi.distanceSqToSegment(Je.start,Je.end,h,l),h.distanceTo(l)<wa*.5&&t.push({point:h,pointOnLine:l,distance:fi.origin.distanceTo(h),object:i,face:null,faceIndex:o,uv:null,uv1:null})}}function Jv(i,t,e){let n=t.projectionMatrix,s=i.material.resolution,r=i.matrixWorld,o=i.geometry,c=o.attributes.instanceStart,l=o.attributes.instanceEnd,h=Math.min(o.instanceCount,c.count),u=-t.near;fi.at(1,di),di.w=1,di.applyMatrix4(t.matrixWorldInverse),di.applyMatrix4(n),di.multiplyScalar(1/di.w),di.x*=s.x/2,di.y*=s.y/2,di.z=0,Nd.copy(di),Pd.multiplyMatrices(t.matrixWorldInverse,r);for(let d=0,f=h;d<f;d++){if(qe.fromBufferAttribute(c,d),Ye.fromBufferAttribute(l,d),qe.w=1,Ye.w=1,qe.applyMatrix4(Pd),Ye.applyMatrix4(Pd),qe.z>u&&Ye.z>u)continue;if(qe.z>u){let w=qe.z-Ye.z,p=(qe.z-u)/w;qe.lerp(Ye,p)}else if(Ye.z>u){let w=Ye.z-qe.z,p=(Ye.z-u)/w;Ye.lerp(qe,p)}qe.applyMatrix4(n),Ye.applyMatrix4(n),qe.multiplyScalar(1/qe.w),Ye.multiplyScalar(1/Ye.w),qe.x*=s.x/2,qe.y*=s.y/2,Ye.x*=s.x/2,Ye.y*=s.y/2,Je.start.copy(qe),Je.start.z=0,Je.end.copy(Ye),Je.end.z=0;let _=Je.closestPointToPointParameter(Nd,!0);Je.at(_,Up);let m=Ma.lerp(qe.z,Ye.z,_),x=m>=-1&&m<=1,v=Nd.distanceTo(Up)<wa*.5;if(x&&v){Je.start.fromBufferAttribute(c,d),Je.end.fromBufferAttribute(l,d),Je.start.applyMatrix4(r),Je.end.applyMatrix4(r);let w=new k,p=new k;fi.distanceSqToSegment(Je.start,Je.end,p,w),e.push({point:p,pointOnLine:w,distance:fi.origin.distanceTo(p),object:i,face:null,faceIndex:d,uv:null,uv1:null})}}}var Cd,Lp,Dp,qe,Ye,di,Nd,Pd,Je,Up,ll,hl,ui,fi,wa,dl,Fp=ca(()=>{fs();Rd();Id();Cd=new re,Lp=new k,Dp=new k,qe=new re,Ye=new re,di=new re,Nd=new k,Pd=new se,Je=new ga,Up=new k,ll=new Ue,hl=new We,ui=new re;dl=class extends an{constructor(t=new ms,e=new ps({color:Math.random()*16777215})){super(t,e),this.isLineSegments2=!0,this.type="LineSegments2"}computeLineDistances(){let t=this.geometry,e=t.attributes.instanceStart,n=t.attributes.instanceEnd,a=new Float32Array(2*e.count);for(let r=0,o=0,c=e.count;r<c;r++,o+=2)Lp.fromBufferAttribute(e,r),Dp.fromBufferAttribute(n,r),a[o]=o===0?0:a[o-1],a[o+1]=a[o]+Lp.distanceTo(Dp);let s=new Xi(a,2,1);return t.setAttribute("instanceDistanceStart",new Yn(s,1,0)),t.setAttribute("instanceDistanceEnd",new Yn(s,1,1)),this}raycast(t,e){let n=this.material.worldUnits,a=t.camera;if(a===null&&!n&&console.error('LineSegments2: "Raycaster.camera" needs to be set in order to raycast against LineSegments2 while worldUnits is set to false.'),n===!1&&(this.material.resolution.x===0||this.material.resolution.y===0))return;let s=t.params.Line2!==void 0&&t.params.Line2.threshold||0;fi=t.ray;let r=this.matrixWorld,o=this.geometry,c=this.material;wa=c.linewidth+s,o.boundingSphere===null&&o.computeBoundingSphere(),hl.copy(o.boundingSphere).applyMatrix4(r);let l;if(n)l=wa*.5;else{let u=Math.max(a.near,hl.distanceToPoint(fi.origin));l=Op(a,u,c.resolution)}if(hl.radius+=l,fi.intersectsSphere(hl)===!1)return;o.boundingBox===null&&o.computeBoundingBox(),ll.copy(o.boundingBox).applyMatrix4(r);let h;if(n)h=wa*.5;else{let u=Math.max(a.near,ll.distanceToPoint(fi.origin));h=Op(a,u,c.resolution)}ll.expandByScalar(h),fi.intersectsBox(ll)!==!1&&(n?Yv(this,e):Jv(this,a,e))}onBeforeRender(t){let e=this.material.uniforms;e&&e.resolution&&(t.getViewport(Cd),this.material.uniforms.resolution.value.set(Cd.z,Cd.w))}}});var gs={};Eu(gs,{AmbientLight:()=>_r,BackSide:()=>Xe,BatchedMesh:()=>ir,Box3:()=>Ue,BufferAttribute:()=>mn,BufferGeometry:()=>Le,ByteType:()=>Tr,Color:()=>Ht,ConeGeometry:()=>lr,CylinderGeometry:()=>ns,DataTexture:()=>Ai,DirectionalLight:()=>yr,DoubleSide:()=>Bn,FloatType:()=>bn,FrontSide:()=>oi,GridHelper:()=>Sr,Group:()=>Si,IntType:()=>cs,Line:()=>ma,Line3:()=>ga,LineBasicMaterial:()=>pa,LineLoop:()=>ar,LineMaterial:()=>ps,LineSegments:()=>ts,LineSegments2:()=>dl,LineSegmentsGeometry:()=>ms,MathUtils:()=>Ma,Matrix3:()=>Bt,Matrix4:()=>se,Mesh:()=>an,MeshBasicMaterial:()=>$a,MeshLambertMaterial:()=>pr,NearestFilter:()=>Pe,Object3D:()=>Oe,OrbitControls:()=>ol,PerspectiveCamera:()=>pn,Plane:()=>fn,Points:()=>sr,REVISION:()=>mc,RGBAFormat:()=>xn,RGBAIntegerFormat:()=>hs,RGFormat:()=>li,RGIntegerFormat:()=>ls,Ray:()=>Jn,Raycaster:()=>Mr,RedFormat:()=>Rr,RedIntegerFormat:()=>va,Scene:()=>$s,ShortType:()=>Ir,Sphere:()=>We,SphereGeometry:()=>dr,TOUCH:()=>ri,TorusGeometry:()=>ur,Triangle:()=>ii,UnsignedByteType:()=>sn,UnsignedIntType:()=>wn,UnsignedShortType:()=>Yi,Vector2:()=>Ut,Vector3:()=>k,Vector4:()=>re,WebGLRenderer:()=>il});var bs=ca(()=>{fs();Np();Id();Fp();Rd()});var gS={};Eu(gS,{default:()=>mS,explorer:()=>Fd,mesh:()=>pu});var Bp=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Kv=globalThis[Bp]||(globalThis[Bp]=(bs(),Ra(gs))),{AmbientLight:kp,BackSide:ul,BatchedMesh:JE,Box3:on,BufferAttribute:ze,BufferGeometry:Zn,ByteType:KE,Color:kn,ConeGeometry:zp,CylinderGeometry:Vp,DataTexture:ZE,DirectionalLight:Hp,DoubleSide:Li,FloatType:QE,FrontSide:pi,GridHelper:Gp,Group:fl,IntType:$E,Line:tT,Line3:zn,LineBasicMaterial:Vr,LineLoop:eT,LineSegments:pl,MathUtils:nT,Matrix3:iT,Matrix4:Ke,Mesh:cn,MeshBasicMaterial:Wp,MeshLambertMaterial:jp,NearestFilter:aT,Object3D:sT,PerspectiveCamera:Xp,Plane:xs,Points:rT,REVISION:Ld,RGBAFormat:oT,RGBAIntegerFormat:cT,RGFormat:lT,RGIntegerFormat:hT,Ray:qp,Raycaster:ml,RedFormat:dT,RedIntegerFormat:uT,Scene:Yp,ShortType:fT,Sphere:pT,SphereGeometry:Jp,TOUCH:Kp,TorusGeometry:Zp,Triangle:Di,UnsignedByteType:mT,UnsignedIntType:gT,UnsignedShortType:bT,Vector2:ln,Vector3:it,Vector4:xT,WebGLRenderer:Qp}=Kv;var Dd=new it(0,1,0),Ud=new it,gl=class i{constructor(t){this.root=new fl,t.add(this.root),this.owned=[],this.materials={},this.cylinder=this.own(new Vp(1,1,1,18,1).translate(0,.5,0)),this.cone=this.own(new zp(1,1,24,1).translate(0,.5,0)),this.sphere=this.own(new Jp(1,28,18)),this.triGeometry=this.own(new Zn),this.triGeometry.setAttribute("position",new ze(new Float32Array(9),3)),this.front=this.add(new cn(this.triGeometry,this.material("front",{side:pi,offset:!0}))),this.back=this.add(new cn(this.triGeometry,this.material("back",{side:ul,offset:!0}))),this.paraGeometry=this.own(new Zn),this.paraGeometry.setAttribute("position",new ze(new Float32Array(18),3)),this.para=this.add(new cn(this.paraGeometry,this.material("para",{side:Li,opacity:.28}))),this.paraEdges=[this.stick("paraEdge"),this.stick("paraEdge")],this.edges=[this.stick("edge"),this.stick("edge"),this.stick("edge")],this.ring=[0,1,2].map(()=>this.add(new cn(this.cone,this.material("ring")))),this.vertices={};for(let e of"ABC")this.vertices[e]=this.add(new cn(this.sphere,this.material(e)));this.u=this.arrow("U"),this.v=this.arrow("V"),this.n=this.arrow("N"),this.unit=this.arrow("unit",{opacity:.45}),this.cue=new fl,this.root.add(this.cue),this.cueArc=new cn(void 0,this.material("N")),this.cueHead=new cn(this.cone,this.material("N")),this.cueHead.rotation.z=-Math.PI/2,this.cue.add(this.cueArc,this.cueHead),this.cueArcAngle=null,this.arcs=new Map,this.line=this.stick("line"),this.axes={};for(let e of"xyz")this.axes[e]={arrow:this.arrow(e),ticks:[]};this.grid=null}own(t){return this.owned.push(t),t}add(t){return this.root.add(t),t}material(t,{side:e=pi,opacity:n=1,offset:a=!1}={}){let s=t+":"+e+":"+n+":"+a;if(!this.materials[s]){let r=new Wp({side:e,transparent:n<1,opacity:n,depthWrite:n>=1});a&&Object.assign(r,{polygonOffset:!0,polygonOffsetFactor:1,polygonOffsetUnits:1}),r.userData.role=t,this.materials[s]=r}return this.materials[s]}paint(t){for(let e of Object.values(this.materials))e.color.set(t(e.userData.role))}arrow(t,e={}){let n=new fl,a=new cn(this.cylinder,this.material(t,e)),s=new cn(this.cone,this.material(t,e));return n.add(a,s),this.root.add(n),{group:n,shaft:a,head:s}}stick(t){return this.add(new cn(this.cylinder,this.material(t)))}static placeStick(t,e,n,a){Ud.subVectors(n,e);let s=Ud.length();t.visible=s>0,s&&(t.position.copy(e),t.quaternion.setFromUnitVectors(Dd,Ud.divideScalar(s)),t.scale.set(a,s,a))}static placeArrow(t,e,n,a,s=!0){let r=new it().subVectors(n,e),o=r.length();if(t.group.visible=s&&o>0,!t.group.visible)return;let c=Math.min(7*a,.45*o),l=Math.min(2.6*a,c*.5);t.group.position.copy(e),t.group.quaternion.setFromUnitVectors(Dd,r.divideScalar(o)),t.shaft.scale.set(a,o-c*.9,a),t.head.position.set(0,o-c,0),t.head.scale.set(l,c,l)}setAxes(t,e,n,a,s){let r=[];for(let o of"xyz"){let c=new it(o==="x"?1:0,o==="y"?1:0,o==="z"?1:0),l=this.axes[o];i.placeArrow(l.arrow,c.clone().multiplyScalar(-t),c.clone().multiplyScalar(t),n,s);let h=s?Math.floor(t/e+1e-9):0;for(;l.ticks.length<2*h;)l.ticks.push(this.add(new cn(this.sphere,this.material(o))));l.ticks.forEach((u,d)=>{let f=d<h?d+1:-(d-h+1);u.visible=d<2*h&&Math.abs(f*e)<t-1e-9,u.position.copy(c).multiplyScalar(f*e),u.scale.setScalar(n*1.9),u.visible&&f>0&&r.push({axis:o,value:f*e,position:u.position.clone()})})}return r}setGrid(t,e,n,a){if(this.grid&&(this.root.remove(this.grid),this.grid.geometry.dispose(),this.grid.material.dispose(),this.grid=null),!a)return;let s=Math.max(2,Math.round(4*t/e));this.grid=new Gp(2*t,s,n.gridMajor,n.grid),this.grid.rotation.x=Math.PI/2,this.grid.material.depthWrite=!1,this.grid.renderOrder=-1,this.root.add(this.grid)}update(t){let{A:e,P:n,Q:a,centroid:s,r}=t,o=this.triGeometry.attributes.position;[e,n,a].forEach((h,u)=>o.setXYZ(u,h.x,h.y,h.z)),o.needsUpdate=!0,this.triGeometry.computeBoundingSphere(),this.front.visible=this.back.visible=!t.degenerate;for(let h of"ABC"){let u=this.vertices[h];u.position.copy(t[h]),u.scale.setScalar(r*(t.degenerate?3.4:2.5))}let c=[e,n,a];for(let h=0;h<3;h++){let u=c[h],d=c[(h+1)%3];i.placeStick(this.edges[h],u,d,r*.45);let f=this.ring[h],b=new it().subVectors(d,u),_=b.length();if(f.visible=!t.degenerate&&_>0,f.visible){let m=Math.min(4.5*r,.22*_),x=new it().addVectors(u,d).multiplyScalar(.5).lerp(s,.22);f.quaternion.setFromUnitVectors(Dd,b.divideScalar(_)),f.position.copy(x).addScaledVector(b,-m/2),f.scale.set(m*.45,m,m*.45)}}i.placeArrow(this.u,e,n,r),i.placeArrow(this.v,e,a,r);let l=s.clone().add(t.nDraw);i.placeArrow(this.n,s,l,r*1.15,!t.degenerate),i.placeArrow(this.unit,s,t.unitDraw?s.clone().add(t.unitDraw):s,r*1.9,!t.degenerate&&!!t.unitDraw),this.updateCue(t),this.updateParallelogram(t),this.updateLine(t)}updateCue(t){let e=t.nDraw.clone(),n=e.length();if(t.degenerate||!n){this.cue.visible=!1;return}e.divideScalar(n);let a=new it().subVectors(t.P,t.A),s=new it().subVectors(t.Q,t.A),r=a.clone().addScaledVector(e,-a.dot(e)).normalize(),o=new it().crossVectors(e,r),c=Math.atan2(s.dot(o),s.dot(r));c>0||(c=Math.PI/2),c=Math.max(c,.45*Math.PI);let l=Math.PI/36,h=Math.round(c/l);this.arcs.has(h)||this.arcs.set(h,new Zp(1,.055,8,48,h*l)),this.cueArc.geometry=this.arcs.get(h),this.cueArcAngle=h*l;let u=this.cueArcAngle;this.cueHead.position.set(Math.cos(u),Math.sin(u),0),this.cueHead.rotation.set(0,0,u),this.cueHead.position.addScaledVector(new it(-Math.sin(u),Math.cos(u),0),-.12),this.cueHead.scale.set(.16,.32,.16);let d=.32*Math.min(a.length(),s.length(),1.2*n)+1e-9,f=new Ke().makeBasis(r,o,e);this.cue.quaternion.setFromRotationMatrix(f),this.cue.position.copy(t.centroid).addScaledVector(e,.3*n),this.cue.scale.setScalar(Math.max(d,3*t.r)),this.cue.visible=!0}updateParallelogram(t){let e=t.showParallelogram&&!t.degenerate;if(this.para.visible=e,this.paraEdges.forEach(s=>s.visible=e),!e)return;let n=new it().addVectors(t.P,t.Q).sub(t.A),a=this.paraGeometry.attributes.position;[t.P,n,t.Q,t.P,n,t.Q].forEach((s,r)=>a.setXYZ(r,s.x,s.y,s.z)),a.needsUpdate=!0,this.paraGeometry.computeBoundingSphere(),i.placeStick(this.paraEdges[0],t.P,n,t.r*.45),i.placeStick(this.paraEdges[1],t.Q,n,t.r*.45),t.D=n}updateLine(t){if(this.line.visible=!1,!t.degenerate)return;let e=[t.A,t.B,t.C],n=null,a=0;for(let l=0;l<3;l++)for(let h=l+1;h<3;h++){let u=e[l].distanceTo(e[h]);u>a&&([a,n]=[u,[e[l],e[h]]])}if(!n||a<t.r)return;let s=new it().subVectors(n[1],n[0]).normalize(),r=Math.max(.35*a,6*t.r),o=n[0].clone().addScaledVector(s,-r),c=n[1].clone().addScaledVector(s,r);i.placeStick(this.line,o,c,t.r*.9)}pickables(){return Object.entries(this.vertices).map(([t,e])=>({name:t,mesh:e}))}dispose(){this.setGrid(0,1,null,!1);for(let t of this.arcs.values())t.dispose();for(let t of this.owned)t.dispose();for(let t of Object.values(this.materials))t.dispose();this.root.removeFromParent()}};var Zv=/^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/,Qv=/^([+-]?\d+)\s*\/\s*([+-]?\d+)$/;function Ki(i){let t=String(i??"").trim();if(Zv.test(t))return Number(t);let e=Qv.exec(t);if(e){let n=Number(e[1])/Number(e[2]);return Number.isFinite(n)?n:NaN}return NaN}function $p(i){if(!Array.isArray(i)||i.length!==3)return null;let t=i.map(Ki);return t.every(Number.isFinite)?t:null}function Hr(i){let t=String(i??"0.1").trim(),e=/^(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/.exec(t);if(!e||!(Number(t)>0)||!/\d/.test((e[1]||"")+(e[2]||"")))return{value:.1,decimals:1,units:1};let n=((e[1]||"")+(e[2]||"")).replace(/^0+(?=\d)/,""),a=Number(e[3]||0)-(e[2]||"").length;for(;n.length>1&&n.endsWith("0");)n=n.slice(0,-1),a+=1;let s=Math.max(0,-a),r=Number(n)*10**(a+s);return{value:r/10**s,decimals:s,units:r}}function $v(i){let t=new DataView(new ArrayBuffer(8));t.setFloat64(0,i);let e=t.getBigUint64(0),n=e>>63n===1n,a=Number(e>>52n&0x7ffn),s=e&(1n<<52n)-1n;a&&(s|=1n<<52n);let r=(a||1)-1075,o=n?-s:s;return r>=0?[o<<BigInt(r),1n]:[o,1n<<BigInt(-r)]}function tM(i,t){if(!Number.isFinite(i))return 0;let[e,n]=$v(i),a=10n**BigInt(t.decimals),s=BigInt(t.units),o=((e<0n?-e:e)*a*2n+n*s)/(2n*n*s);return Number(e<0n?-o:o)}function Gr(i,t,e){let n=tM(i,t);if(Array.isArray(e)&&e.length===2){let a=Math.ceil(Number(e[0])/t.value-1e-9),s=Math.floor(Number(e[1])/t.value+1e-9);Number.isFinite(a)&&(n=Math.max(n,a)),Number.isFinite(s)&&(n=Math.min(n,s))}return n===0?0:n}function Od(i,t,e){return Math.abs(i-t*e.value)<=1e-9*Math.max(1,Math.abs(i))}function Wr(i,t){let e=BigInt(i)*BigInt(t.units),n=e<0n,a=(n?-e:e).toString();return t.decimals>0&&(a=a.padStart(t.decimals+1,"0"),a=a.slice(0,-t.decimals)+"."+a.slice(-t.decimals)),(n?"-":"")+a}function tm(i){return!(i>0)||!Number.isFinite(i)?1:10**Math.floor(Math.log10(i))}function em(i){if(!(i>0))return 1;let t=10**Math.floor(Math.log10(i));for(let e of[1,2,5,10])if(e*t>=i*(1-1e-9))return e*t;return 10*t}function nm(i){if(i===0)return"0";let t=Math.abs(i);return t>=1e5||t<.001?i.toExponential(0).replace("e+","e"):String(Number(i.toPrecision(6)))}var eM=22,im=(i,t)=>i.toLowerCase()+"xyz"[t],am={ArrowRight:[0,1],ArrowLeft:[0,-1],ArrowUp:[1,1],ArrowDown:[1,-1],PageUp:[2,1],PageDown:[2,-1]};function sm(i){let t=new ml,e=new ln,n=new xs,a=null,s=null,r=0;function o(p,y){let S=i.canvas.getBoundingClientRect();return e.set((p-S.left)/S.width*2-1,-((y-S.top)/S.height)*2+1),t.setFromCamera(e,i.camera),t.ray}function c(p,y){return o(p,y).intersectPlane(n,new it)}function l(p,y){let S=i.canvas.getBoundingClientRect(),g=null,M=eM;for(let E of"ABC"){let A=i.position(E);if(!A)continue;let I=A.clone().project(i.camera),C=S.left+(I.x+1)/2*S.width,P=S.top+(1-I.y)/2*S.height,N=Math.hypot(C-p,P-y);N<M&&([g,M]=[E,N])}return g}function h(p,y){let S=i.position(p);if(!S)return!1;let g=i.camera.getWorldDirection(new it);n.setFromNormalAndCoplanarPoint(g,S);let M=c(y.clientX,y.clientY);if(!M)return!1;let E=i.values(p).slice();return a={name:p,pointerId:y.pointerId,hit:M,strings:E,moved:new Set,start:E.map((A,I)=>{let C=Ki(A);return Number.isFinite(C)?C:S.getComponent(I)*i.scale()})},i.container.setPointerCapture(y.pointerId),i.container.classList.add("tnx-dragging"),i.dragging(!0,p),!0}function u(){if(r=0,!a||!s)return;let p=c(s.clientX,s.clientY);if(s=null,!p)return;let y=p.sub(a.hit).multiplyScalar(i.scale()),S=i.grid(),g=i.values(a.name),M={};a.strings.forEach((E,A)=>{let I=E,C=y.getComponent(A);if(Math.abs(C)>=S.value/2){let P=Gr(a.start[A]+C,S,i.bounds());Od(a.start[A],P,S)||(I=Wr(P,S))}I!==E&&a.moved.add(A),a.moved.has(A)&&I!==g[A]&&(M[im(a.name,A)]=I)}),Object.keys(M).length&&i.write(M)}function d(p){if(a||p.button>0||p.pointerType==="touch"&&i.touchActive&&!i.touchActive())return;let y=p.target.closest?.("[data-vertex]"),S=y?y.dataset.vertex:p.target===i.canvas?l(p.clientX,p.clientY):null;S&&h(S,p)&&(p.preventDefault(),p.stopPropagation(),y&&y.focus({preventScroll:!0}))}function f(p){if(!a){p.target===i.canvas&&p.buttons===0&&(i.canvas.style.cursor=l(p.clientX,p.clientY)?"grab":"");return}p.pointerId===a.pointerId&&(p.preventDefault(),s={clientX:p.clientX,clientY:p.clientY},r||(r=requestAnimationFrame(u)))}function b(p){let y=a.name;a=null,s=null,i.container.classList.remove("tnx-dragging"),i.container.hasPointerCapture?.(p)&&i.container.releasePointerCapture(p),i.dragging(!1,y)}function _(p){!a||p.pointerId!==a.pointerId||(s&&(cancelAnimationFrame(r),r=0,p.type!=="pointercancel"&&u()),b(p.pointerId))}function m(){a&&(r&&cancelAnimationFrame(r),r=0,b(a.pointerId))}function x(p){let y=p.target.closest?.("[data-vertex]");if(!y||!(p.key in am)||p.altKey||p.ctrlKey||p.metaKey)return;p.preventDefault();let S=y.dataset.vertex,[g,M]=am[p.key],E=i.values(S)[g],A=i.grid(),I=Ki(E);Number.isFinite(I)||(I=(i.position(S)?.getComponent(g)??0)*i.scale());let C=Gr(I+M*A.value,A,i.bounds());if(Od(I,C,A))return;let P=Wr(C,A);P!==E&&i.write({[im(S,g)]:P})}let v=i.container;v.addEventListener("pointerdown",d,{capture:!0}),v.addEventListener("pointermove",f),v.addEventListener("pointerup",_),v.addEventListener("pointercancel",_),v.addEventListener("keydown",x);let w=()=>{r&&cancelAnimationFrame(r),v.removeEventListener("pointerdown",d,{capture:!0}),v.removeEventListener("pointermove",f),v.removeEventListener("pointerup",_),v.removeEventListener("pointercancel",_),v.removeEventListener("keydown",x)};return w.cancel=m,w}function Xt(i,t,e){let n=document.createElement(i);return t&&(n.className=t),e!==void 0&&(n.textContent=e),n}function ys(i,t){let e=Object.entries(t);for(let[n,a]of e)i.addEventListener(n,a);return()=>{for(let[n,a]of e)i.removeEventListener(n,a)}}function bl(i,t){let e=Xt("div",i);return e.setAttribute("role","toolbar"),e.setAttribute("aria-label",t),e}function Zi(i,t){let e=String(t);i.textContent!==e&&(i.textContent=e)}function _n(i,t,e){let n=String(e);i.getAttribute(t)!==n&&i.setAttribute(t,n)}function Vn(i,t){i.hidden!==!!t&&(i.hidden=!!t)}var rm=new WeakMap;function Aa(i,t,e){let n=rm.get(i);n||rm.set(i,n={}),n[t]!==e&&(n[t]=e,i.style[t]=e)}var jr=new it;function om(i,t,e){return jr.copy(i).project(t),{x:(jr.x+1)/2*e.width,y:(1-jr.y)/2*e.height,behind:jr.z>1||jr.z<-1}}var xl=class{constructor(t){this.el=document.createElement("div"),this.el.className="tnx-labels",t.appendChild(this.el),this.items=new Map}label(t,e,n){let a=this.items.get(t);if(!a){let s=document.createElement("div");s.className="tnx-label tnx-"+e,this.el.appendChild(s),a={el:s,kind:e,anchor:null,away:null,offset:0,visible:!0,text:null},this.items.set(t,a)}return n!==void 0&&a.text!==n&&(a.el.textContent=n,a.text=n,a.half=null),a}place(t,e,{away:n=null,offset:a=0,angle:s=null,visible:r=!0}={}){let o=this.items.get(t);o&&(o.anchor=e?e.clone():null,o.away=n?n.clone():null,o.offset=a,o.angle=s,o.visible=r&&!!e)}hide(t){for(let[e,n]of this.items)e.startsWith(t)&&(n.visible=!1)}layout(t,e){let n=[];for(let a of this.items.values()){if(!a.visible||!a.anchor){Vn(a.el,!0);continue}let s=om(a.anchor,t,e);if(s.behind){Vn(a.el,!0);continue}let r=0,o=0;if(a.offset){let h=0,u=0;if(a.away){let f=om(a.away,t,e);h=s.x-f.x,u=s.y-f.y}let d=Math.hypot(h,u);d<8&&a.angle!==null?(h=Math.cos(a.angle),u=-Math.sin(a.angle)):d<1e-6?(h=0,u=-1):(h/=d,u/=d),r=h*a.offset,o=u*a.offset}let c=s.x+r,l=s.y+o;if(a.kind==="vertex"){for(let h of n)Math.hypot(h.x-c,h.y-l)<30&&a.angle!==null&&(c=s.x+Math.cos(a.angle)*a.offset*1.4,l=s.y-Math.sin(a.angle)*a.offset*1.4);c=Math.min(Math.max(c,20),e.width-20),l=Math.min(Math.max(l,20),e.height-20),n.push({x:c,y:l})}if(Vn(a.el,!1),a.kind==="arrow"){(!a.half||!a.half.w)&&(a.half={w:a.el.offsetWidth/2,h:a.el.offsetHeight/2});let{w:h,h:u}=a.half;e.width>2*h+4&&(c=Math.min(Math.max(c,h+2),e.width-h-2)),e.height>2*u+4&&(l=Math.min(Math.max(l,u+2),e.height-u-2))}a.el.style.transform=`translate(${c.toFixed(1)}px, ${l.toFixed(1)}px) translate(-50%, -50%)`}}dispose(){this.el.remove(),this.items.clear()}};function Qn(i,t,e){let n=document.createElement(i);return(i==="input"||i==="select")&&(n.dataset.lmSuppressShortcuts="true"),t&&(n.className=t),e!==void 0&&(n.textContent=e),n}function cm(i,t){let e=Qn("div","tnx-controls");e.setAttribute("role","group"),e.setAttribute("aria-label","Coordinates");let n={};for(let c of"abc"){let l=Qn("div","tnx-vertex-row"),h=Qn("span","tnx-vertex-name",c.toUpperCase()),u=Qn("span","tnx-coords");l.append(h,u),n[c]={name:h,cells:[]},["x","y","z"].forEach((d,f)=>{let b=Qn("span","tnx-coord"),_=Qn("input","tnx-slider");_.type="range",_.setAttribute("aria-label",`${c.toUpperCase()}.${d} slider`);let m=Qn("input","tnx-exact");m.type="text",m.spellcheck=!1,m.autocomplete="off",m.setAttribute("aria-label",`${c.toUpperCase()}.${d}, exact value: type a number such as 0.1, -2 or 1/3 and press Enter`),m.title=`${c.toUpperCase()}.${d}: type a number such as 0.1, -2 or 1/3 and press Enter`,b.append(Qn("span","tnx-axis-name",d),_,m),u.appendChild(b),n[c].cells.push({slider:_,box:m});let x=0;_.addEventListener("input",()=>{x||(x=requestAnimationFrame(()=>{x=0;let w=Hr(t.get("step")),p=Gr(Number(_.value),w,t.get("bounds")),y=Wr(p,w);String((t.get(c)||[])[f]??"")!==y&&(m.value=y,t.edit({[c+d]:y}))}))}),m.addEventListener("input",()=>{m.dataset.dirty="true"});let v=()=>{m.dataset.dirty&&(delete m.dataset.dirty,t.edit({[c+d]:m.value}))};m.addEventListener("change",v),m.addEventListener("keydown",w=>{w.key==="Enter"?v():w.key==="Escape"&&(delete m.dataset.dirty,m.value=String((t.get(c)||[])[f]??""))})}),e.appendChild(l)}let a=Qn("div","tnx-settings"),s=Qn("label","tnx-decimals","decimals "),r=Qn("select");s.appendChild(r),r.addEventListener("change",()=>t.edit({precision:Number(r.value)})),a.appendChild(s),e.appendChild(a),i.appendChild(e);function o(){Vn(e,t.get("show_controls")===!1);let c=Hr(t.get("step")),[l,h]=(t.get("bounds")||[-5,5]).map(Number);for(let b of"abc"){Aa(n[b].name,"color",t.color(b.toUpperCase()));let _=(t.get(b)||["","",""]).map(String);n[b].cells.forEach(({slider:m,box:x},v)=>{_n(m,"min",l),_n(m,"max",h),_n(m,"step",c.value);let w=Ki(_[v]);Number.isFinite(w)&&Number(m.value)!==w&&(m.value=String(w)),_n(m,"aria-valuetext",_[v]),!x.dataset.dirty&&x.value!==_[v]&&(x.value=_[v])})}let[u,d]=t.get("precision_range")||[0,15];if(r.options.length!==d-u+1){r.textContent="";for(let b=u;b<=d;b++)r.appendChild(new Option(String(b),String(b)))}let f=String(t.get("precision")??4);r.value!==f&&(r.value=f)}return{el:e,update:o,reset(){for(let c of"abc")for(let{box:l}of n[c].cells)delete l.dataset.dirty},dispose(){e.remove()}}}function nM(i,t){if(i.dataset.text===t)return;i.dataset.text=t,i.textContent="";let e=String(t).startsWith("("),n=e?i.appendChild(document.createElement("span")):i;e&&(n.className="tnx-vector");let a=String(t).split(/(?<=,) | (?=[+=−-] )/);a.forEach((s,r)=>{let o=document.createElement("span");o.className="tnx-part",o.textContent=s,n.appendChild(o),r<a.length-1&&n.appendChild(document.createTextNode(" "))})}function lm(i){let t=document.createElement("section");t.className="tnx-readout",t.setAttribute("aria-label","Readout");let e=document.createElement("table");e.className="tnx-table";let n=document.createElement("tbody");e.appendChild(n);let a=document.createElement("p");a.className="tnx-status";let s=document.createElement("p");s.className="tnx-summary",s.setAttribute("aria-live","polite"),s.setAttribute("role","status"),t.append(e,a,s),i.appendChild(t);let r=0;function o(c){let l=Array.isArray(c?.readout)?c.readout:[];for(;n.rows.length>l.length;)n.deleteRow(-1);l.forEach((u,d)=>{let f=n.rows[d]||n.insertRow();if(f.cells.length===0){let b=document.createElement("th");b.scope="row",f.append(b,document.createElement("td")),f.cells[1].className="tnx-value"}_n(f,"data-key",u.key),Zi(f.cells[0],u.label),nM(f.cells[1],c.ok===!1?"—":u.value)}),Zi(a,(c?.ok===!1?c.error:c?.status)||""),_n(a,"data-state",c?.ok===!1?"error":c?.degenerate?"degenerate":"ok"),clearTimeout(r);let h=c?.ok===!1?c.error||"":c?.summary||c?.status||"";r=setTimeout(()=>{s.textContent!==h&&(s.textContent=h)},350)}return{el:t,update:o,show(c){Vn(t,!c)},dispose(){clearTimeout(r),t.remove()}}}var hm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),iM=globalThis[hm]||(globalThis[hm]=(bs(),Ra(gs))),{OrbitControls:dm}=iM;var Pn=new it(1,.75,.65).normalize(),um=40,fm=28;function aM(){try{let i=document.createElement("canvas").getContext("webgl2");if(!i)return!1;let t=i.getExtension("WEBGL_debug_renderer_info"),e=t?String(i.getParameter(t.UNMASKED_RENDERER_WEBGL)):"";return i.getExtension("WEBGL_lose_context")?.loseContext(),/swiftshader|llvmpipe|softpipe|software/i.test(e)}catch{return!1}}function yl(i,{onRender:t}){let e=new Qp({antialias:!aM()});e.setPixelRatio(Math.min(window.devicePixelRatio||1,2));let n=e.domElement;n.className="tnx-canvas",i.appendChild(n);let a=new Yp,s=new Xp(um,1,.01,1e3);s.up.set(0,0,1),s.position.copy(Pn).multiplyScalar(6);let r=new dm(s,n);r.enableDamping=!1,r.zoomToCursor=!1;let o=0,c=1,l=1,h={target:new it,distance:6,radius:1,points:[new it],center:new it,direction:Pn.clone(),start:Pn.clone()},u=!0;function d(){o=0,t(),e.render(a,s)}function f(){o||(o=requestAnimationFrame(d))}function b(){o&&cancelAnimationFrame(o),d()}function _(){let E=Math.max(1,Math.round(i.clientWidth)),A=Math.max(1,Math.round(i.clientHeight));E===c&&A===l||(c=E,l=A,e.setSize(E,A,!1),s.aspect=E/A,s.updateProjectionMatrix(),u&&M(h.direction),f())}function m(E){let A=E.clone().normalize(),I=new it().crossVectors(s.up,A);return I.lengthSq()<1e-12&&I.set(1,0,0),I.normalize(),{x:I,y:new it().crossVectors(A,I),z:A}}function x(E){let{x:A,y:I}=m(E),C=h.points.map(z=>z.clone().sub(h.center).dot(A)),P=h.points.map(z=>z.clone().sub(h.center).dot(I)),N=(Math.min(...C)+Math.max(...C))/2,U=(Math.min(...P)+Math.max(...P))/2;return h.center.clone().addScaledVector(A,N).addScaledVector(I,U)}function v(E){let{x:A,y:I,z:C}=m(E),P=Math.tan(um/2*Math.PI/180),N=P*s.aspect,U=Math.max(.5,1-2*fm/Math.max(c,1)),z=Math.max(.5,1-2*fm/Math.max(l,1)),F=1e-6;for(let K of h.points){let H=K.clone().sub(h.target),J=H.dot(C);F=Math.max(F,J+Math.abs(H.dot(A))/(N*U),J+Math.abs(H.dot(I))/(P*z))}return Math.max(F*1.02,h.radius*1.2)}let w=new ResizeObserver(_);w.observe(i),r.addEventListener("change",f),r.addEventListener("start",()=>{u=!1});function p(E,A=!0,I=null){I&&h.start.copy(I),h.points=E.map(N=>N.clone());let C=E[0].clone(),P=E[0].clone();for(let N of E)C.min(N),P.max(N);h.center.copy(C).add(P).multiplyScalar(.5),h.target.copy(h.center),h.radius=Math.max(P.distanceTo(C)/2,.001),A==="keep"?M(s.position.clone().sub(r.target)):A&&M(h.start)}function y(E,A){let I=s.position.clone().sub(r.target),C=I.length(),P=Math.atan2(I.y,I.x)+E,N=Math.PI/2-.01,U=Math.max(-N,Math.min(N,Math.asin(Math.max(-1,Math.min(1,I.z/C)))+A));I.set(Math.cos(U)*Math.cos(P),Math.cos(U)*Math.sin(P),Math.sin(U)).multiplyScalar(C),s.position.copy(r.target).add(I),u=!1,r.update()}function S(E){let A=s.position.clone().sub(r.target).multiplyScalar(E),I=Math.min(Math.max(A.length(),s.near*2),s.far/2);s.position.copy(r.target).addScaledVector(A.normalize(),I),u=!1,r.update()}function g(E,A=.92){return s.updateMatrixWorld(),E.every(I=>{let C=I.clone().project(s);return Math.abs(C.x)<=A&&Math.abs(C.y)<=A&&C.z<1})}function M(E){h.direction.copy(E),u=!0;let A=E.clone().normalize();Math.abs(A.z)>.999&&A.set(0,-.001,Math.sign(A.z)).normalize(),h.target.copy(x(A)),h.distance=v(A),s.near=h.distance/200,s.far=h.distance*50,s.updateProjectionMatrix(),r.target.copy(h.target),s.position.copy(h.target).addScaledVector(A,h.distance),s.lookAt(h.target),r.update(),f()}return{renderer:e,canvas:n,scene:a,camera:s,controls:r,requestRender:f,renderNow:b,resize:_,framePoints:p,inView:g,reset:()=>M(h.start),turn:y,zoom:S,atHome:()=>u,along:E=>M(new it(E==="x"?1:0,E==="y"?-1:0,E==="z"?1:0)),setBackground:E=>{a.background=new kn(E),f()},size:()=>({width:c,height:l}),dispose(){o&&cancelAnimationFrame(o),w.disconnect(),r.dispose(),e.dispose(),e.forceContextLoss?.(),n.remove()}}}var pm=".tn-view{--tn-bg: #fff;--tn-fg: #1a1a1a;--tn-muted: #4a4f5c;font:15px/1.4 system-ui,-apple-system,Segoe UI,Roboto,sans-serif;color:var(--tn-fg);max-width:100%}.tn-view.tn-dark{--tn-bg: #1b1d24;--tn-fg: #f2f2f2;--tn-muted: #c3c7d1}";function _l(i,t,e){for(let[n,a]of[["trinormal-view-base",pm],[t,e]]){if(i.getElementById(n))continue;let s=i.createElement("style");s.id=n,s.textContent=a,i.head.appendChild(s)}}var mm=".tnx-root{--tnx-chip: rgba(255,255,255,.92);display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}.tnx-root.tn-dark{--tnx-chip: rgba(27,29,36,.9)}.tnx-main{flex:1 1 400px;min-width:min(360px,100%);max-width:100%}.tnx-side{flex:1 1 250px;min-width:min(100%,min-content);max-width:100%;container-type:inline-size}.tnx-side.tnx-no-readout{flex-basis:100%}.tnx-toolbar{display:flex;flex-wrap:wrap;gap:4px;margin:0 0 6px;container-type:inline-size}.tnx-toolbar button{font:inherit;font-size:14px;line-height:1.2;padding:5px 7px;min-height:32px;min-width:32px;flex:0 0 auto;white-space:nowrap;border-radius:6px;cursor:pointer;border:1px solid var(--tn-muted);background:var(--tn-bg);color:var(--tn-fg)}.tnx-short{display:none}@container (max-width: 470px){.tnx-toolbar .tnx-long{display:none}.tnx-toolbar .tnx-short{display:inline}.tnx-toolbar button{padding:5px 6px}}.tnx-toolbar button[aria-pressed=true]{background:var(--tn-fg);color:var(--tn-bg)}.tnx-toolbar button:focus-visible,.tnx-vertex:focus-visible{outline:3px solid #0072B2;outline-offset:2px}.tnx-stage{position:relative;width:100%;height:var(--tnx-height,clamp(170px, calc(100vh - 310px) ,370px));max-height:80vh;min-height:170px;overflow:hidden;border:1px solid var(--tn-muted);border-radius:0;background:var(--tn-bg);touch-action:pan-y;user-select:none;-webkit-user-select:none}.tnx-canvas{display:block;width:100%!important;height:100%!important;outline:none}.tnx-labels{position:absolute;inset:0;pointer-events:none;overflow:hidden}.tnx-label{position:absolute;left:0;top:0;white-space:nowrap;font-weight:700;font-size:19px;line-height:1;will-change:transform}.tnx-arrow,.tnx-axis,.tnx-tick,.tnx-note{padding:2px 4px;border-radius:4px;background:var(--tnx-chip)}.tnx-tick{font-weight:400;font-size:14px;color:var(--tn-fg)}.tnx-note{font-weight:600;font-size:14px;color:var(--tn-fg)}.tnx-vertex{pointer-events:auto;cursor:grab;touch-action:pan-y;min-width:34px;min-height:34px;display:flex;align-items:center;justify-content:center;font-size:19px;border-radius:50%;border:3px solid currentColor;background:var(--tnx-chip)}.tnx-dragging .tnx-vertex,.tnx-dragging .tnx-canvas{cursor:grabbing}.tnx-touch-active .tnx-stage,.tnx-touch-active .tnx-vertex{touch-action:none}.tnx-touch-active .tnx-stage{outline:3px solid #0072B2;outline-offset:-3px}.tnx-message,.tnx-error{margin:6px 0 0;padding:4px 10px;border-radius:6px;font-size:15px;border-left:5px solid #e69f00;color:var(--tn-fg)}.tnx-error,.tnx-message[data-state=error]{border-left-color:#d55e00;font-weight:700}.tnx-tick{z-index:1}.tnx-axis{z-index:2}.tnx-arrow{z-index:3}.tnx-vertex{z-index:5}.tnx-legend{margin:6px 0 0;padding:0 10px;font-size:15px;color:var(--tn-fg)}.tnx-hint{margin:6px 0 0;font-size:14px;color:var(--tn-muted)}.tnx-readout{min-width:0;font-size:15px}.tnx-root .tnx-readout table{border-collapse:collapse;width:100%}.tnx-root .tnx-readout th{text-align:left;line-height:1.25;padding:1px 10px 1px 0;white-space:nowrap;font-weight:700;vertical-align:top}.tnx-root .tnx-readout td{padding:1px 0;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;line-height:1.25}.tnx-root .tnx-vector,.tnx-root .tnx-part{white-space:nowrap}@container (max-width: 340px){.tnx-readout tr,.tnx-readout th,.tnx-root .tnx-readout td{display:block}.tnx-root .tnx-readout .tnx-vector{white-space:normal}.tnx-root .tnx-readout td{padding:0 0 4px .8em}}.tnx-status{margin:6px 0 0;padding:4px 8px;border-left:4px solid #009e73}.tnx-status[data-state=degenerate]{border-left-color:#e69f00}.tnx-status[data-state=error]{border-left-color:#d55e00;font-weight:700}.tnx-summary{position:absolute;width:1px;height:1px;margin:-1px;overflow:hidden;clip:rect(0 0 0 0);white-space:nowrap}.tnx-nogl{padding:12px;border:1px solid var(--tn-muted);border-radius:6px}.tnx-controls{flex:1 1 100%;display:flex;flex-direction:column;gap:4px;font-size:15px}.tnx-vertex-row{display:flex;align-items:baseline;gap:4px 12px}.tnx-vertex-name{flex:none;font-weight:700;font-size:16px;width:1.2em}.tnx-coords{display:flex;flex-wrap:wrap;align-items:center;gap:4px 12px;min-width:0}.tnx-coord{display:inline-flex;align-items:center;gap:4px}.tnx-axis-name{display:inline-block;width:.8em;color:var(--tn-muted)}.tnx-slider{width:7em;margin:0;accent-color:#0072B2}.tnx-exact,.tnx-decimals select{font:inherit;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;width:4.6em;padding:2px 4px;border:1px solid var(--tn-muted);border-radius:4px;background:var(--tn-bg);color:var(--tn-fg)}.tnx-decimals select{width:auto}.tnx-exact:focus-visible,.tnx-slider:focus-visible,.tnx-decimals select:focus-visible{outline:3px solid #0072B2;outline-offset:1px}";var gm={A:{light:"#333333",dark:"#E6E6E6"}};function _s(i=document){let t=i.body;return t?t.dataset.jpThemeLight!==void 0?t.dataset.jpThemeLight==="false":t.dataset.mdColorScheme!==void 0?t.dataset.mdColorScheme==="slate":i.documentElement.dataset.mdColorScheme==="slate":!1}function vl(i,t=document){let e=_s(t),n=new MutationObserver(()=>{let s=_s(t);s!==e&&(e=s,i(e))}),a=["data-md-color-scheme","data-jp-theme-light","data-jp-theme-name"];return t.body&&n.observe(t.body,{attributes:!0,attributeFilter:a}),n.observe(t.documentElement,{attributes:!0,attributeFilter:a}),()=>n.disconnect()}function Xr(i,t,e){let n=i&&i[t]||gm[t]||gm.A;return e?n.dark:n.light}function Qi(i){return i?{background:"#1b1d24",text:"#f2f2f2",grid:"#4a4f5c",gridMajor:"#6b7180",line:"#ffd166"}:{background:"#ffffff",text:"#1a1a1a",grid:"#d4d7de",gridMajor:"#9aa0ab",line:"#b3261e"}}var oM=10,cM=600;function Ml({root:i,stageEl:t,controls:e,canvas:n,activeClass:a}){let s=!1;function r(d){s=d,i.classList.toggle(a,d),e.touches.ONE=d?Kp.ROTATE:null,n.style.touchAction=d?"none":"pan-y"}r(!1);let o=null,c=d=>{o=d.pointerType==="touch"?{x:d.clientX,y:d.clientY,t:performance.now(),id:d.pointerId}:null},l=d=>{if(!o||d.pointerId!==o.id)return;let f=Math.hypot(d.clientX-o.x,d.clientY-o.y)<oM&&performance.now()-o.t<cM;o=null,f&&!s&&r(!0)},h=d=>{s&&!i.contains(d.target)&&r(!1)},u=i.ownerDocument||document;return t.addEventListener("pointerdown",c,{capture:!0}),t.addEventListener("pointerup",l),u.addEventListener("pointerdown",h,{capture:!0}),{active:()=>s,dispose(){t.removeEventListener("pointerdown",c,{capture:!0}),t.removeEventListener("pointerup",l),u.removeEventListener("pointerdown",h,{capture:!0})}}}var Sl=["a","b","c","winding","precision","step","bounds","show_parallelogram","show_unit_normal","show_readout","show_controls","precision_range","palette","state","message"],vm={a:["ax","ay","az"],b:["bx","by","bz"],c:["cx","cy","cz"]},Mm=new Set(Object.values(vm).flat()),lM=new Set([...Mm,"winding","precision","show_parallelogram","show_unit_normal"]),bm=.7,xm=.5;function hM(i,t){return!(i>0)||!(t>0)||!Number.isFinite(i)?1:2**Math.round(Math.log2(t/i))}function wl(i,t){let e=hM(i,t);return{factor:e,length:i*e}}var dM="⁰¹²³⁴⁵⁶⁷⁸⁹";function uM(i){let t=Math.round(Math.log2(i));return Math.abs(t)<=12?String(2**Math.abs(t)):"2"+[...String(Math.abs(t))].map(e=>dM[Number(e)]).join("")}function ym(i,t=!1){if(i===1)return t?"N/|N|":"N";let e=uM(i);return i<1?t?`N/(${e}|N|)`:`N/${e}`:t?`${e}N/|N|`:`${e}N`}var fM={A:225*Math.PI/180,B:-30*Math.PI/180,C:90*Math.PI/180},_m={ABC:"A→B→C",ACB:"A→C→B"};function pM(i){if(!(i.length()>0))return Pn.clone();let t=i.clone().normalize(),e=Pn.dot(t);if(e>=.35&&e<=.8)return Pn.clone();let n=Pn.clone(),a=Math.abs(Pn.dot(t)-.65);for(let s of[20,35,55])for(let r=0;r<8;r++){let o=(r*45+37)*Math.PI/180,c=s*Math.PI/180,l=new it(Math.cos(c)*Math.cos(o),Math.cos(c)*Math.sin(o),Math.sin(c)),h=Math.abs(l.dot(t)-.65);h<a-1e-9&&([n,a]=[l,h])}return n}function vs(i,t,e){let n=Xt("button","tnx-button",i);return n.type="button",t&&(n.setAttribute("aria-label",t),n.title=t),n.addEventListener("click",e),n}var mM=0;function gM({model:i,el:t}){_l(t.ownerDocument||document,"trinormal-explorer-style",mm);let e=`v${++mM}-${Math.random().toString(36).slice(2,8)}`,n=Xt("div","tn-view tnx-root");n.dataset.lmSuppressShortcuts="true";let a=Xt("div","tnx-main"),s=Xt("div","tnx-side"),r=bl("tnx-toolbar","3D view"),o=Xt("div","tnx-stage"),c=Xt("p","tnx-message");c.hidden=!0,c.setAttribute("role","status");let l=Xt("p","tnx-legend");l.hidden=!0;let h=Xt("p","tnx-error");h.hidden=!0,h.setAttribute("role","alert");let u=Xt("p","tnx-hint","Drag empty space to turn the view, scroll or pinch to zoom; x, y, z look along an axis. Drag A, B or C to move a point, or Tab to it and press the arrow keys (x, y) or Page Up/Page Down (z). On a touch screen, tap the view first, then drag.");a.append(r,o,c,h,l),n.append(a,s),t.appendChild(n);let d=lm(s);s.appendChild(u);let f=0,b={};function _(et){let vt=vm[et];if(!vt||!vt.some(ne=>ne in b))return et in b?b[et].value:i.get(et);let At=i.get(et)||["","",""];return vt.map((ne,Vt)=>ne in b?b[ne].value:At[Vt])}function m(et){f+=1;for(let[vt,At]of Object.entries(et)){let ne=!Mm.has(vt)||Number.isFinite(Ki(At));lM.has(vt)&&ne&&(b[vt]={value:At,seq:f})}i.send({edit:et,seq:f,view:e,base:i.get("version")??0})}let x=_s(),v=et=>{let vt=Qi(x);switch(et){case"edge":case"paraEdge":case"ring":case"unit":return vt.text;case"para":return Xr(_("palette"),"N",x);case"line":return vt.line;default:return Xr(_("palette"),et,x)}},w=cm(n,{get:_,edit:m,color:et=>v(et)}),p;try{p=yl(o,{onRender:()=>y.layout(p.camera,p.size())})}catch{o.remove(),u.remove(),a.appendChild(Xt("p","tnx-nogl","This browser cannot draw the 3D view (WebGL is not available). The readout still follows the values."));let vt=()=>{d.show(!0),d.update(i.get("state")),w.update()};vt();for(let At of Sl)i.on("change:"+At,vt);return()=>{for(let At of Sl)i.off("change:"+At,vt);n.remove()}}let y=new xl(o),S=new gl(p.scene),g=vs("",null,()=>m({winding:_("winding")==="ACB"?"ABC":"ACB"})),M=(et,vt)=>vs(vt,null,()=>m({[et]:!_(et)})),E=M("show_parallelogram","");E.append(Xt("span","tnx-long","Parallelogram"),Xt("span","tnx-short","▱")),E.setAttribute("aria-label","Parallelogram");let A=M("show_unit_normal","N/|N|");A.setAttribute("aria-label","Unit normal N/|N|"),A.title="Show the unit normal N/|N|",E.title="Show the parallelogram on U and V (area |N|)";let I=vs("","Reset view",()=>{P&&ft(tt(U||J(),_("winding")),!0),p.reset()});I.append(Xt("span","tnx-long","Reset view"),Xt("span","tnx-short","Reset")),I.title="Reset view: frame the triangle and its arrows again",r.append(I,vs("x","View along the x axis",()=>p.along("x")),vs("y","View along the y axis",()=>p.along("y")),vs("z","View along the z axis",()=>p.along("z")),g,E,A);let C={};for(let et of"ABC"){let At=y.label("v:"+et,"vertex",et).el;At.dataset.vertex=et,At.tabIndex=0,At.dataset.lmSuppressShortcuts="true",At.setAttribute("role","button"),At.setAttribute("aria-roledescription","movable point"),At.setAttribute("aria-keyshortcuts","ArrowLeft ArrowRight ArrowUp ArrowDown PageUp PageDown"),C[et]=At}for(let[et,vt]of[["U","U"],["V","V"],["N","N"],["unit","N/|N|"]])y.label("arrow:"+et,"arrow",vt);for(let et of"xyz")y.label("axis:"+et,"axis",et);let P=null,N=!1,U=null,z=!1,F=null,K={},H={};function J(){let et=[_("a"),_("b"),_("c")].map($p);if(et.every(Boolean))return et;let vt=_("state");if(vt&&vt.ok&&vt.points){let At=["A","B","C"].map(ne=>vt.points[ne]);if(At.every(ne=>Array.isArray(ne)&&ne.every(Number.isFinite)))return At}return U}function tt(et,vt){let At=Math.max(...et.flat().map(Math.abs)),ne=[[0,1],[0,2],[1,2]].map(([j,ut])=>Math.hypot(...et[j].map((D,Q)=>D-et[ut][Q]))),Vt=Math.max(...ne),Se=Vt===0?!0:At<=6*Vt,ge=tm(Se?At||Vt||1:Vt),B=Se?new it:new it(...[0,1,2].map(j=>Number(((et[0][j]+et[1][j]+et[2][j])/3).toPrecision(3)))),Te=et.map(j=>new it(j[0]-B.x,j[1]-B.y,j[2]-B.z).divideScalar(ge)),ie=Math.max(...Te.map(j=>Math.max(Math.abs(j.x),Math.abs(j.y),Math.abs(j.z)))),te=em(Math.max(ie,1e-9)/1.5),lt=te*(Math.floor(ie/te+1e-9)+1.5),de=Te.slice(),[Et,Nt,L]=Te,T=new it().crossVectors(Nt.clone().sub(Et),L.clone().sub(Et));vt==="ACB"&&T.negate();let V=Math.max(Et.distanceTo(Nt),Et.distanceTo(L),Nt.distanceTo(L)),at=Et.clone().add(Nt).add(L).divideScalar(3);T.length()>0&&(de.push(at.clone().add(T.clone().setLength(wl(T.length()*ge,bm*V).length))),_("show_unit_normal")&&de.push(at.clone().add(T.clone().setLength(wl(1/ge,xm*V).length))));let $=de[0].clone(),rt=de[0].clone();for(let j of de)$.min(j),rt.max(j);let dt=$.clone().add(rt).multiplyScalar(.5),Z=Math.max(rt.distanceTo($)/2,.001);return{S:ge,offset:B,includeOrigin:Se,radius:Z,center:dt,box:de,L:lt,t:te,start:pM(T)}}function ft(et,vt){P=et,vt!==!1&&p.framePoints(et.box,vt,et.start);let At=P.radius*.014,ne=S.setAxes(et.L,et.t,At*.5,v,et.includeOrigin);S.setGrid(et.L,et.t,Qi(x),et.includeOrigin),y.hide("tick:"),ne.forEach((Vt,Se)=>{let xe=`tick:${Vt.axis}:${Se}`;y.label(xe,"tick",nm(Vt.value*et.S)),y.place(xe,Vt.position,{offset:16,angle:Vt.axis==="z"?0:-Math.PI/2})});for(let Vt of"xyz"){let Se=new it(Vt==="x"?et.L:0,Vt==="y"?et.L:0,Vt==="z"?et.L:0);y.place("axis:"+Vt,Se,{away:new it,offset:18,visible:et.includeOrigin}),Aa(y.items.get("axis:"+Vt).el,"color",v(Vt))}}function Ct(et,vt){return et&&vt&&et.S===vt.S&&et.includeOrigin===vt.includeOrigin&&et.offset.equals(vt.offset)}function q(et){let vt=_("state"),At=vt&&vt.ok!==!1&&Array.isArray(vt.readout)?vt.readout.find(ne=>ne.key===et):null;return At?At.value:null}function st(){let et=J(),vt=_("state")||{},At=_("winding")==="ACB"?"ACB":"ABC";Zi(g,`⇄ ${_m[At]}`),_n(g,"aria-label",`Flip the order of the vertices, now ${_m[At]}`),_n(g,"title",g.getAttribute("aria-label")),_n(E,"aria-pressed",!!_("show_parallelogram")),_n(A,"aria-pressed",!!_("show_unit_normal")),d.show(!!_("show_readout")),s.classList.toggle("tnx-no-readout",!_("show_readout")),_("show_readout")&&d.update(vt);let ne=vt.ok===!1?vt.error||vt.status:vt.degenerate?vt.status:"";Vn(c,!ne),Zi(c,ne||""),_n(c,"data-state",vt.ok===!1?"error":"degenerate");let Vt=i.get("message")||"";Vn(h,!Vt),Zi(h,Vt),w.update();for(let nt of"ABC"){let ot=_(nt.toLowerCase())||[];_n(C[nt],"aria-label",`Point ${nt} at (${ot.join(", ")}). Arrow keys move x and y, Page Up and Page Down move z.`)}if(!et){S.root.visible=!1,p.requestRender();return}if(S.root.visible=!0,U=et,!N){let nt=tt(et,At);if(!P)ft(nt,!0);else if(z)ft(nt,p.atHome()?!0:"keep");else if(!Ct(P,nt))ft(nt,"keep");else{(nt.L!==P.L||nt.t!==P.t)&&ft({...nt,center:P.center,radius:P.radius},!1);let ot=et.map(ht=>new it(ht[0]-P.offset.x,ht[1]-P.offset.y,ht[2]-P.offset.z).divideScalar(P.S));p.inView(ot)||ft(nt,"keep")}}z=!1;let{S:Se,offset:xe}=P,[ge,B,Te]=et.map(nt=>new it(nt[0]-xe.x,nt[1]-xe.y,nt[2]-xe.z).divideScalar(Se)),[ie,te]=At==="ABC"?[B,Te]:[Te,B],lt=ge.clone().add(B).add(Te).divideScalar(3),de=ie.clone().sub(ge),Et=te.clone().sub(ge),Nt=new it().crossVectors(de,Et),L=Nt.length(),T=!!vt.degenerate||!(L>0)||!Number.isFinite(L),V=Math.max(de.length(),Et.length(),ie.distanceTo(te),1e-9),at=new it,$=1;if(!T){let nt=wl(L*Se,bm*V);$=nt.factor,at=Nt.clone().setLength(nt.length)}let rt=null,dt=1;if(!T&&_("show_unit_normal")){let nt=wl(1/Se,xm*V);dt=nt.factor,rt=Nt.clone().setLength(nt.length)}y.label("arrow:N","arrow",ym($)),y.label("arrow:unit","arrow",ym(dt,!0)),H={N:$,unit:rt?dt:null};let Z=P.radius*.014,j={A:ge,B,C:Te,P:ie,Q:te,centroid:lt,nDraw:at,unitDraw:rt,degenerate:T,showParallelogram:!!_("show_parallelogram"),r:Z};S.update(j),F={A:ge,B,C:Te},K={U:ie,V:te,N:T?null:lt.clone().add(at),unit:rt?lt.clone().add(rt):null};for(let nt of"ABC")y.place("v:"+nt,j[nt],{away:lt,offset:30,angle:fM[nt]}),Aa(C[nt],"color",v(nt));y.place("arrow:U",ge.clone().lerp(ie,.5),{away:lt,offset:20,visible:de.length()>0}),y.place("arrow:V",ge.clone().lerp(te,.5),{away:lt,offset:20,visible:Et.length()>0});let ut=lt.clone().add(at);y.place("arrow:N",ut,{away:lt,offset:20,angle:0,visible:!T}),y.place("arrow:unit",rt?lt.clone().add(rt):null,{away:lt,offset:20,angle:Math.PI,visible:!!rt});for(let[nt,ot]of[["U","U"],["V","V"],["N","N"],["unit","unit"]])Aa(y.items.get("arrow:"+nt).el,"color",v(ot));let D=q("magnitude"),Q=q("area"),Y=j.showParallelogram&&!T&&D!==null&&Q!==null;Vn(l,!Y),Y&&Zi(l,`Parallelogram on U and V: area |N| = ${D}. Triangle: area |N|/2 = ${Q}.`),p.requestRender()}function xt(){if(n.classList.toggle("tn-dark",x),p.setBackground(Qi(x).background),S.paint(v),P){S.setGrid(P.L,P.t,Qi(x),P.includeOrigin);for(let et of"xyz")Aa(y.items.get("axis:"+et).el,"color",v(et))}st()}let It=Ml({root:n,stageEl:o,controls:p.controls,canvas:p.canvas,activeClass:"tnx-touch-active"}),mt=sm({touchActive:It.active,container:o,canvas:p.canvas,camera:p.camera,scale:()=>P?.S??1,grid:()=>Hr(_("step")),bounds:()=>_("bounds"),values:et=>(_(et.toLowerCase())||["","",""]).map(String),position:et=>F?F[et]:null,write(et){m(et),Lt()},dragging(et){N=et,et||st()}}),Ot=!1,Me=()=>{Ot||(Ot=!0,queueMicrotask(()=>{Ot&&(Ot=!1,st())}))},Lt=()=>{Ot=!1,st(),p.renderNow()},$t=()=>xt(),Yt={};for(let et of Sl)Yt[et]=et==="palette"?$t:Me,i.on("change:"+et,Yt[et]);Yt.last_edit=()=>{let et=i.get("last_edit")||{};if(et.view===e){for(let[vt,At]of Object.entries(b))At.seq<=et.seq&&delete b[vt];Me()}},Yt.version=()=>{mt.cancel(),b={},w.reset(),z=!0,Me()},i.on("change:last_edit",Yt.last_edit),i.on("change:version",Yt.version);let qt=vl(et=>{x=et,xt()}),De=et=>et.A.clone().add(et.B).add(et.C).divideScalar(3);return n.tnxProject=()=>{if(!F||!P)return null;let{width:et,height:vt}=p.size();p.camera.updateMatrixWorld();let At={};for(let[xe,ge]of Object.entries({...F,...K})){if(!ge)continue;let B=ge.clone().project(p.camera);At[xe]=[(B.x+1)/2*et,(1-B.y)/2*vt]}let ne=p.camera.position.distanceTo(p.controls.target),Vt=xe=>xe&&F?xe.clone().sub(De(F)).multiplyScalar(P.S).toArray():null,Se={N:Vt(K.N),unit:Vt(K.unit),scales:{...H}};return{width:et,height:vt,distance:ne,points:At,drawn:Se,values:["a","b","c"].map(xe=>(_(xe)||[]).map(String))}},p.resize(),xt(),()=>{for(let et of Sl)i.off("change:"+et,Yt[et]);i.off("change:last_edit",Yt.last_edit),i.off("change:version",Yt.version),It.dispose(),qt(),mt(),y.dispose(),S.dispose(),p.dispose(),d.dispose(),w.dispose(),n.remove()}}var Fd={render:gM};var bM=1500;function xM(i,t,e){let n=i.length/3,a=new Float32Array(18*n),s=0,r=new it,o=new it,c=new it;for(let l=0;l<n;l++){if(r.set(t[3*l],t[3*l+1],t[3*l+2]),!(r.lengthSq()>0))continue;r.normalize();let h=i[3*l],u=i[3*l+1],d=i[3*l+2],f=h+r.x*e,b=u+r.y*e,_=d+r.z*e;c.set(Math.abs(r.z)<.9?0:1,0,Math.abs(r.z)<.9?1:0),o.crossVectors(r,c).normalize().multiplyScalar(.22*e);let m=f-r.x*.35*e,x=b-r.y*.35*e,v=_-r.z*.35*e;a.set([h,u,d,f,b,_,f,b,_,m+o.x,x+o.y,v+o.z,f,b,_,m-o.x,x-o.y,v-o.z],s),s+=18}return a.subarray(0,s)}function Sm(i,t){let e=Math.max(1,Math.ceil(i/t)),n=new Int32Array(Math.ceil(i/e));for(let a=0,s=0;a<i;a+=e,s++)n[s]=a;return n}function yM(i,t){let e=Sm(t.length/3,2e3),n=[];for(let a of e){let s=t[3*a],r=t[3*a+1];n.push(Math.hypot(i[3*s]-i[3*r],i[3*s+1]-i[3*r+1],i[3*s+2]-i[3*r+2]))}return n.sort((a,s)=>a-s),n.length?n[n.length>>1]:.1}function _M(i,t){let e=i.arrow_faces||new Int32Array(0),n=i.arrow_normals||new Float32Array(0);if(!e.length||n.length!==3*e.length)return null;let a=new Float32Array(3*e.length);for(let s=0;s<e.length;s++)for(let r=0;r<3;r++){let o=i.faces[3*e[s]+r];for(let c=0;c<3;c++)a[3*s+c]+=t[3*o+c]/3}return{starts:a,dirs:n}}function vM(i,t){let e=i.vertex_normals;if(!e||e.length!==t.length)return null;let n=Sm(t.length/3,bM),a=new Float32Array(3*n.length),s=new Float32Array(3*n.length);return n.forEach((r,o)=>{for(let c=0;c<3;c++)a[3*o+c]=t[3*r+c],s[3*o+c]=e[3*r+c]}),{starts:a,dirs:s}}function wm(i){let t={face:new Vr,vertex:new Vr},e={};function n(r,o){let c=new Zn;c.setAttribute("position",new ze(r,3));let l=new pl(c,o);return l.renderOrder=2,i.add(l),l}function a(r,o){let c=.5*yM(o,r.faces);for(let[l,h]of[["face",_M(r,o)],["vertex",vM(r,o)]])h&&(e[l]=n(xM(h.starts,h.dirs,c),t[l]))}function s(){for(let r of Object.values(e))i.remove(r),r.geometry.dispose();e={}}return{draw:a,has:r=>!!e[r],count:r=>e[r]?e[r].geometry.getAttribute("position").count/6:0,show(r,o){e[r]&&(e[r].visible=o)},setColors(r,o){t.face.color=new kn(r),t.vertex.color=new kn(o)},clear:s,dispose(){s();for(let r of Object.values(t))r.dispose()}}}function $i(i,t){if(!t)return new i(0);if(ArrayBuffer.isView(t)&&!(t instanceof DataView))return t;let{buffer:e,byteOffset:n,byteLength:a}=t;return n%i.BYTES_PER_ELEMENT===0?new i(e,n,a/i.BYTES_PER_ELEMENT):new i(e.slice(n,n+a))}function Am(i){let t=i.get("mesh");if(t)return t;let e=i.get("positions");return!e||!e.byteLength?null:{positions:$i(Float64Array,e),faces:$i(Uint32Array,i.get("faces")),flipped:$i(Int32Array,i.get("flipped")),boundary:$i(Int32Array,i.get("boundary")),non_manifold:$i(Int32Array,i.get("non_manifold")),arrow_faces:$i(Int32Array,i.get("arrow_faces")),arrow_normals:$i(Float32Array,i.get("arrow_normals")),vertex_normals:$i(Float32Array,i.get("vertex_normals"))}}function MM(i){let t=[1/0,1/0,1/0],e=[-1/0,-1/0,-1/0];for(let s=0;s<i.length;s+=3)for(let r=0;r<3;r++){let o=i[s+r];o<t[r]&&(t[r]=o),o>e[r]&&(e[r]=o)}if(!(t[0]<=e[0]))return{offset:[0,0,0],scale:1};let n=t.map((s,r)=>(s+e[r])/2),a=Math.hypot(e[0]-t[0],e[1]-t[1],e[2]-t[2])/2;return{offset:n,scale:a>0&&Number.isFinite(a)?2/a:1}}function Em(i){let{offset:t,scale:e}=MM(i),n=new Float32Array(i.length);for(let a=0;a<n.length;a++)n[a]=(i[a]-t[a%3])*e;return{pos:n,offset:t,scale:e}}var SM=4096;function Tm(i){let t=i.length/3,e=[];for(let r of[-1,0,1])for(let o of[-1,0,1])for(let c of[-1,0,1])(r||o||c)&&e.push([r,o,c]);let n=e.map(()=>[-1/0,0]);for(let r=0;r<t;r++){let o=i[3*r],c=i[3*r+1],l=i[3*r+2];for(let h=0;h<e.length;h++){let u=e[h],d=u[0]*o+u[1]*c+u[2]*l;d>n[h][0]&&(n[h]=[d,r])}}let a=new Set(n.map(r=>r[1])),s=Math.max(1,Math.ceil(t/SM));for(let r=0;r<t;r+=s)a.add(r);return[...a].map(r=>new it(i[3*r],i[3*r+1],i[3*r+2]))}function Im(i,t,e){let n=e.flipped.length?e.flipped:e.boundary.length?e.boundary:e.non_manifold;if(!n.length)return Pn.clone();let a=new it;for(let s=0;s<n.length;s++){let r=t[n[s]];a.x+=i[3*r],a.y+=i[3*r+1],a.z+=i[3*r+2]}return a.divideScalar(n.length),a.length()>1e-6?a.normalize().multiplyScalar(3).add(Pn).normalize():Pn.clone()}var wM=0;function Rm(i,t){return i.tabIndex=0,i.setAttribute("role","img"),i.setAttribute("aria-label","The model in 3D. Arrow keys turn it, + and − zoom, Home resets the view."),ys(i,{keydown:n=>{let a=(n.shiftKey?45:15)*(Math.PI/180),r={ArrowLeft:()=>t.turn(-a,0),ArrowRight:()=>t.turn(a,0),ArrowUp:()=>t.turn(0,a),ArrowDown:()=>t.turn(0,-a),"+":()=>t.zoom(.8),"=":()=>t.zoom(.8),"-":()=>t.zoom(1.25),Home:()=>t.reset()}[n.key];!r||n.altKey||n.ctrlKey||n.metaKey||(n.preventDefault(),r())}})}function Cm({onPick:i,picked:t}){let e=Xt("form","tnm-keys"),n=`tnm-face-${++wM}`,a=Xt("label","tnm-face-label","Face number");a.htmlFor=n;let s=Xt("input","tnm-face-input");Object.assign(s,{id:n,type:"number",min:"0",step:"1",inputMode:"numeric",autocomplete:"off"});let r=Xt("button","tnm-button","Show face");r.type="submit";let o=Xt("button","tnm-button","Previous face to flip"),c=Xt("button","tnm-button","Next face to flip");o.type=c.type="button",e.append(a,s,r,o,c);let l=null;function h(){let d=s.value.trim();if(!d||!s.checkValidity()){s.reportValidity();return}i(Number(d))}e.addEventListener("submit",d=>{d.preventDefault(),h()}),s.addEventListener("keydown",d=>{d.key==="Enter"&&(d.preventDefault(),h())});function u(d){if(!l||!l.length)return;let f=t(),b=d>0?l.findIndex(_=>_>f):l.findLastIndex(_=>_<f);b<0&&(b=d>0?0:l.length-1),s.value=String(l[b]),i(l[b])}return o.addEventListener("click",()=>u(-1)),c.addEventListener("click",()=>u(1)),{form:e,update(d,f){l=f||null,a.textContent=d?`Face number (0 to ${d-1})`:"Face number",o.hidden=c.hidden=!(l&&l.length)},showPicked(d){s.ownerDocument.activeElement!==s&&(s.value=String(d))}}}var Ms=(function(){var i="b9H79Tebbbe;veC9Geueu9Geub9Gbb9Gsuuuuuuuuuuuu99uueu9Gvuuuuub9Gruuuuuuub9Gouuuuuue999Gvuuuuueu9Gzuuuuuuuuuuu99uuuub9Gquuuuuuu99uueu9GPuuuuuuuuuuu99uueu9Gquuuuuuuu99ueu9Gruuuuuu99eu9Gwuuuuuu99ueu9Giuuue999GDuuuuuuuuueu9Gkuuuuuuuu99uub9Gluuuueu9Gluuuub9Giuuueui3EdilvorlwDiqkrxmPszdHObAAbeAlve9Weiiviebeoweuecj:Gdkr:Sdmo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bbz9TW79O9V9Wt9F79P9T9W29P9M95bw8E9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9OcttV9P9I91tW7bD8A9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9O9v9W9K9HtWbqQ9TW79O9V9Wt9F79P9T9W29P9M959t29V9W9W95bkX9TW79O9V9Wt9F79P9T9W29P9M959qV919UWbmQ9TW79O9V9Wt9F79P9T9W29P9M959q9V9P9Ut7bPX9TW79O9V9Wt9F79P9T9W29P9M959t9J9H2WbsP9TW79O9V9Wt9FVW9TW79Obza9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94SWt9J9O9sW9T9H9WbA59TW79O9V9Wt9F9NW9UWV9HtW9q9V79Pt9P9V9U9sW9T9H9WbCl79IV9RbXDwebcekdKYq:p:1dElbzOk:Q:tekYue99iuQ99eui99Due99xue9:w998Jjjjjbcj;sb9Rgs8Kjjjjbcbhzasc:Cefcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkdnamcdGTmbalcrfci4cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egecdtfaHBdbasaecefBd;8ecbhlcbhednadTmbabheadhOinaHaeydbci4fcb86bbaeclfheaOcufgOmbkcbhlabheadhOinaHaeydbgAci4fgCaCRbbgCceaAcrGgAtV86bbaCcu7aA4ceGalfhlaeclfheaOcufgOmbkcualcdtalcFFFFi0Ehekaecbyd;y:L:cjbHjjjjbbhzasc:Cefasyd;8egecdtfazBdbasaecefBd;8ealcd4alfhOcehHinaHgecethHaeaO6mbkcbhXcuaecdtgOaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egAcdtfaHBdbasaAcefBd;8eaHcFeaOz:xjjjbhQdnadTmbaecufhLcbhKindndnaQabaKcdtfgYydbgAc:v;t;h;Ev2aLGgOcdtfgCydbgHcuSmbceheinazaHcdtfydbaASmdaOaefhHaecefheaQaHaLGgOcdtfgCydbgHcu9hmbkkazaXcdtfaABdbaCaXBdbaXhHaXcefhXkaYaHBdbaKcefgKad9hmbkkaQcbyd;C:L:cjbH:bjjjbbasasyd;8ecufBd;8ekcbh8AcualcefgecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhKasc:Cefasyd;8egecdtfaKBdbasaKBdNeasaecefBd;8ecuadcitadcFFFFe0Ecbyd;y:L:cjbHjjjjbbhEasc:Cefasyd;8egecdtfaEBdbasaEBd:yeasaecefBd;8eascNefabadalcbz:cjjjbcualcdtgealcFFFFi0Eg3cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egOcdtfaHBdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhXasc:Cefasyd;8egOcdtfaXBdbasaOcefBd;8eaHaXaialavazasc:Cefz:djjjbalcbyd;y:L:cjbHjjjjbbh5asc:Cefasyd;8egOcdtfa5BdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhOasc:Cefasyd;8egAcdtfaOBdbasaAcefBd;8ea3cbyd;y:L:cjbHjjjjbbhAasc:Cefasyd;8egCcdtfaABdbasaCcefBd;8eaOcFeaez:xjjjbh8EaAcFeaez:xjjjbh8FdnalTmbindnaKa8AgAcefg8AcdtfydbgCaKaAcdtgefydbgOSmbaCaO9RhYaEaOcitfhaa8Faefhha8EaefhLcbhCindndnaaaCcitfydbgQaA9hmbaLaABdbahaABdbxekdnaKaQcdtggfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheinaeydbaASmdaecwfheaOcufgOmbkka8FagfgeaAaQaeydbcuSEBdbaLaQaAaLydbcuSEBdbkaCcefgCaY9hmbkka8Aal9hmbkaHhOaXhAa8EhQa8FhCcbheindndnaeaOydbgL9hmbdnaeaAydbgL9hmbaQydbhLdnaCydbgYcu9hmbaLcu9hmba5aefcb86bbxikdnaYcuSmbaLcuSmbaeaYSmbaHaYcdtfydbaHaLcdtfydb9hmba5aefcd86bbxika5aefhadnaeaYSmbaeaLSmbaace86bbxikaacv86bbxdkdnaeaXaLcdtgYfydb9hmbdnaCydbgacuSmbaeaaSmbaQydbggcuSmbaeagSmba8FaYfydbghcuSmbahaLSmba8EaYfydbgYcuSmbaYaLSmbaHaacdtfydbgLaHaYcdtfydb9hmbaLaHagcdtfydbgYSmbaYaHahcdtfydb9hmba5aefcd86bbxika5aefcv86bbxdka5aefcv86bbxeka5aefa5aLfRbb86bbkaOclfhOaAclfhAaQclfhQaCclfhCalaecefge9hmbkdnamcaGTmbcbh8Jindndna5a8Jfg8KRbbg8Lc9:fPlbeebekdndndnaHa8Jcdtfydbgea8J9hmbcbhYcbh8MaqTmednazTmbcbh8Ma8JheinaqazaecdtgefydbfRbbce4a8MVceGh8MaXaefydbgea8J9hmbxikkcbh8Ma8JheinaqaefRbbce4a8MVceGh8MaXaecdtfydbgea8J9hmbxdkka5aefRbbhexeka8JheindnaKaecdtg8AfgeclfydbgOaeydbgeSmbaOae9RhgaEaecitfhhaHa8AfhacbhLinahaLcitfydbgQhednindnaKaecdtgCfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheaaydbhAdninaHaeydbcdtfydbaASmeaecwfheaOcufgOTmdxbkkcbhexdkaXaCfydbgeaQ9hmbkcehekaYaeVhYaLcefgLag9hmbkkaXa8Afydbgea8J9hmbka8LclciaYceGEa8MEheka8Kae86bbka8Jcefg8Jal9hmbkkdnaqTmbdndnazTmbazheaHhOalhAindnaqaeydbfRbbceGTmba5aOydbfcv86bbkaeclfheaOclfhOaAcufgAmbxdkkaqheaHhOalhAindnaeRbbceGTmba5aOydbfcv86bbkaecefheaOclfhOaAcufgAmbkkaHhealhAa5hOindna5aeydbfRbbcv9hmbaOcv86bbkaeclfheaOcefhOaAcufgAmbkkamceGTmba5healhOindndnaeRbbcufPlbeebekaecv86bbkaecefheaOcufgOmbkkcbh8Ncualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh8Kasc:Cefasyd;8egecdtfa8KBdbasaecefBd;8eascbBd:qeas9cb83i1ea8Kaialavazasc1efz:ejjjbhydndnaDmbcbh8PcbhaxekcbhaawhecbhOindnaeIdbJbbbb9ETmbasaacdtfaOBdbaacefhakaeclfheaDaOcefgO9hmbkcuaaal2gecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbh8Pasc:Cefasyd;8egecdtfa8PBdbasaecefBd;8ealTmbdnaambcbhaxekarcd4hgdnazTmbaacdthhcbhLa8PhYinaoazaLcdtfydbag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbxdkkaacdthhcbhLa8PhYinaoaLag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbkkcualc8S2gOalc;D;O;f8U0EgCcbyd;y:L:cjbHjjjjbbheasc:Cefasyd;8egAcdtfaeBdbasaAcefBd;8eaecbaOz:xjjjbhIcbh8RcbhgdnaaTmbcbh8NaCcbyd;y:L:cjbHjjjjbbhgasc:Cefasyd;8egecdtfagBdbasaecefBd;8eagcbaOz:xjjjb8Acuaaal2gecltgOaecFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Rasc:Cefasyd;8egecdtfa8RBdbasaecefBd;8ea8RcbaOz:xjjjb8AamcjjjjdGTmbcualcltgealcFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Nasc:Cefasyd;8egOcdtfa8NBdbasaOcefBd;8ea8Ncbaez:xjjjb8AkdnadTmbcbhQabhOina8KaOclfydbgLcx2fgeIdba8KaOydbgYcx2fgAIdbg8S:tgRa8KaOcwfydbghcx2fgCIdlaAIdlg8U:tg8VNaeIdla8U:tg8WaCIdba8S:tg8XN:tg8Ya8YNa8WaCIdwaAIdwg8Z:tg80NaeIdwa8Z:tg8Wa8VN:tg81a81Na8Wa8XNaRa80N:tg80a80NMMg8V:rhBa8Yh8Xa80h8Wa81hRdna8VJbbbb9EgATmba8YaB:vh8Xa80aB:vh8Wa81aB:vhRkaIaHaYcdtfydbgCc8S2fgeaRaB:rg8VaRNNg83aeIdbMUdbaea8Wa8Va8WNgUNg85aeIdlMUdlaea8Xa8Va8XNg86Ng87aeIdwMUdwaeaRaUNgUaeIdxMUdxaea86aRNg88aeIdzMUdzaea8Wa86Ng89aeIdCMUdCaeaRa8Va8Xa8ZNaRa8SNa8Ua8WNMM:mg8:Ng86NgRaeIdKMUdKaea8Wa86Ng8WaeId3MUd3aea8Xa86Ng8XaeIdaMUdaaea86a8:Ng86aeId8KMUd8Kaea8VaeIdyMUdyaIaHaLcdtfydbgLc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdyaIaHahcdtfydbgYc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdydna8NTmbdnaATmba8YaB:vh8Ya80aB:vh80a81aB:vh81ka8NaCcltfgeaBJbbbZNgRa80Ng8VaeIdlMUdlaeaRa8YNg8WaeIdwMUdwaeaRa81Ng8XaeIdbMUdbaeaRa8S:ma81Na8Ua80N:ta8Za8YN:tNgRaeIdxMUdxa8NaLcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxa8NaYcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxkaOcxfhOaQcifgQad6mbkkdnalTmbJq;x8J88J;n;m;m89J:v:;;w8ZamczGEamc;abGEh80cbhOaHhCazhQaIhea8KhAindnaOaCydb9hmbaOhLdnazTmbaQydbhLka80hRdnaqTmbJbbjZa80aqaLfRbbclGEhRkaecxfgLaLIdbJbbbbMUdbaeczfgLaLIdbJbbbbMUdbaecCfgLaLIdbJbbbbMUdbaeaRaecyfgLIdbg8YNgRaeIdbMUdbaeclfgYaRaYIdbMUdbaecwfgYaRaYIdbMUdbaecKfgYaYIdbaAIdbg8WaRN:tUdbaAcwfIdbh8Vaec3fgYaYIdbaRaAclfIdbg8XN:tUdbaecafgYaYIdbaRa8VN:tUdbaec8KfgYIdbh81aLa8YaRMUdbaYa81aRa8Va8VNa8Wa8WNa8Xa8XNMMNMUdbkaCclfhCaQclfhQaec8SfheaAcxfhAalaOcefgO9hmbkkdnadTmbcbh8AabhLinaba8AcdtfhYcbheindna5aLaefydbgCfRbbgOTmba5aYaec:G:G:cjbfydbcdtfydbgQfRbbcFeGgATmbdnaOclSghmbaOci6mbaAclSmbaAcd0mekdnaOcd0mba8EaCcdtfydbaQ9hmekdnaAcd0mba8FaQcdtfydbaC9hmekdndnahmbaAcl9hmekaOciSmeaAciSmekJbbbZJbbbZJbbacaAcdSEaOcdSEhUdna8KaYaec:K:G:cjbfydbcdtfydbcx2fgOIdwa8KaCcx2fgAIdwg86:tg8Sa8KaQcx2fghIdwa86:tg8Xa8XNahIdbaAIdbg8U:tg80a80NahIdlaAIdlg8Z:tg8Va8VNMMg81Na8Xa8Sa8XNaOIdba8U:tg83a80Na8VaOIdla8Z:tg85NMMg8WN:tg8Ya8YNa83a81Na80a8WN:tgRaRNa85a81Na8Va8WN:tg8Wa8WNMMgBJbbbb9ETmba8YaB:rgB:vh8Ya8WaB:vh8WaRaB:vhRkaUa81:rNgBa8Ya86NaRa8UNa8Za8WNMM:mg81Ng87a81Nh88a80a85Na8Va83N:tg81a81Na8Va8SNa8Xa85N:tg8Va8VNa8Xa83Na80a8SN:tg8Xa8XNMMg83:rh80a8Ya87Nh85a8Wa87Nh89aRa87Nh87a8WaBa8YNg8SNh8:a8SaRNhZaRaBa8WNgnNhca8Ya8SNh8Ya8WanNh8WaRaBaRNNh8Sdna83Jbbbb9ETmba81a80:vh81a8Xa80:vh8Xa8Va80:vh8VkaIaHaCcdtfydbc8S2fgOaOIdba8Sa8VaUa80:rNgRa8VNNMg80MUdbaOa8Wa8XaRa8XNg8SNMg83aOIdlMUdlaOa8Ya81aRa81Ng8WNMg8YaOIdwMUdwaOaca8Va8SNMg8SaOIdxMUdxaOaZa8Wa8VNMgUaOIdzMUdzaOa8:a8Xa8WNMg8WaOIdCMUdCaOa87a8VaRa81a86Na8Va8UNa8Za8XNMMg86:mNgRNMg8VaOIdKMUdKaOa89a8XaRNMg8XaOId3MUd3aOa85a81aRNMg81aOIdaMUdaaOa88a86aRN:tgRaOId8KMUd8KaOaBaOIdyMUdyaIaHaQcdtfydbc8S2fgOa80aOIdbMUdbaOa83aOIdlMUdlaOa8YaOIdwMUdwaOa8SaOIdxMUdxaOaUaOIdzMUdzaOa8WaOIdCMUdCaOa8VaOIdKMUdKaOa8XaOId3MUd3aOa81aOIdaMUdaaOaRaOId8KMUd8KaOaBaOIdyMUdykaeclfgecx9hmbkaLcxfhLa8Acifg8Aad6mbkkdnamcjeGTmbalTmbcbh9cindnaKa9cgecdtgOfydbghaKaecefg9ccdtfydbg8M9pmba8Kaecx2fhDaIaHaOfydbgCc8S2fh8AindnaHaEahcitfgeydbgLcdtfydbg8JaC0mbaeydlh8LcuhAaLheindnaKaecdtgYfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheindnaHaeydbcdtfydbaC9hmbaAcu9hhQaLhAaQmbaeclfydbhAkaecwfheaOcufgOmbkkaXaYfydbgeaL9hmbkaAaLSmbaAcuSmba8KaLcx2fgeIdbaDIdbg81:tgRa8Ka8Lcx2fgOIdlaDIdlg80:tg8XNaeIdla80:tg8VaOIdba81:tg8YN:tg86a8KaAcx2fgAIdba81:tg8Za8VNaAIdla80:tg83aRN:tg8SNa8VaOIdwaDIdwgB:tg8UNaeIdwaB:tg8Wa8XN:tg85a83a8WNaAIdwaB:tg87a8VN:tgUNa8Wa8YNaRa8UN:tg88a87aRNa8Za8WN:tg89NMMa86a86Na85a85Na88a88NMM:rJ:A:z9z:;Na8Sa8SNaUaUNa89a89NMM:rN9Gmbdna8Ua8Wa8WNaRaRNa8Va8VNMMg8SNa8Wa8Ua8WNa8YaRNa8Va8XNMMg86N:tg8Ua8UNa8Ya8SNaRa86N:tg8Ya8YNa8Xa8SNa8Va86N:tg86a86NMMg8XJbbbb9ETmba8Ua8X:rg8X:vh8Ua86a8X:vh86a8Ya8X:vh8Yka8S:rg8Xa8UaBNa8Ya81Na80a86NMM:mgUNg85aUNhUa8Ua85Nh88a86a85Nh89a8Ya85Nh8:a86a8Xa8UNg85NhZa85a8YNhna8Ya8Xa86NgcNhJa8Ua85Nh8Ua86acNh86a8Ya8Xa8YNNh85dna87a8SNa8Wa87a8WNa8ZaRNa8Va83NMMg8YN:tg8Wa8WNa8Za8SNaRa8YN:tgRaRNa83a8SNa8Va8YN:tg8Va8VNMMg8YJbbbb9ETmba8Wa8Y:rg8Y:vh8Wa8Va8Y:vh8VaRa8Y:vhRka8Aa8AIdba85aRa8XaRNNMg8SMUdba8Aa86a8Va8Xa8VNg8ZNMg86a8AIdlMUdla8Aa8Ua8Wa8Xa8WNg8YNMg8Ua8AIdwMUdwa8AaJaRa8ZNMg8Za8AIdxMUdxa8Aana8YaRNMg83a8AIdzMUdza8AaZa8Va8YNMg85a8AIdCMUdCa8Aa8:aRa8Xa8WaBNaRa81Na80a8VNMMg81:mNg8YNMgRa8AIdKMUdKa8Aa89a8Va8YNMg8Va8AId3MUd3a8Aa88a8Wa8YNMg8Wa8AIdaMUdaa8AaUa81a8YN:tg8Ya8AId8KMUd8Ka8Aa8Xa8XMg8Xa8AIdyMUdyaIa8Jc8S2fgea8SaeIdbMUdbaea86aeIdlMUdlaea8UaeIdwMUdwaea8ZaeIdxMUdxaea83aeIdzMUdzaea85aeIdCMUdCaeaRaeIdKMUdKaea8VaeId3MUd3aea8WaeIdaMUdaaea8YaeId8KMUd8Kaea8XaeIdyMUdykahcefgha8M9hmbkka9cal9hmbkkdnadTmbaaTmbcbhYinJbbbbh80a8KabaYcdtfgeclfydbgLcx2fgOIdwa8Kaeydbghcx2fgAIdwg8Z:tg8Va8VNaOIdbaAIdbg83:tg8Wa8WNaOIdlaAIdlg85:tg8Xa8XNMMg8Sa8Kaecwfydbg8Acx2fgeIdwa8Z:tg8YNa8Va8YNa8WaeIdba83:tg81Na8XaeIdla85:tgBNMMgRa8VN:tJbbbbJbbjZa8Sa8Ya8YNa81a81NaBaBNMMg8UNaRaRN:tg86:va86Jbbbb9BEg86Nh88a8Ua8VNaRa8YN:ta86Nh89a8SaBNaRa8XN:ta86Nh8:a8Ua8XNaRaBN:ta86NhZa8Sa81NaRa8WN:ta86Nhna8Ua8WNaRa81N:ta86Nhca8WaBNa8Xa81N:tgRaRNa8Xa8YNa8VaBN:tgRaRNa8Va81Na8Wa8YN:tgRaRNMM:rJbbbZNhRa8Pahaa2g8JcdtfhOa8Pa8Aaa2g8McdtfhAa8PaLaa2gDcdtfhCa8Z:mhJa85:mh9ea83:mhTascjdfheaahQJbbbbhBJbbbbh86Jbbbbh8SJbbbbh8UJbbbbh8ZJbbbbh83Jbbbbh85Jbbbbh87JbbbbhUinaecwfaRa89aCIdbaOIdbg8Y:tg8XNa88aAIdba8Y:tg81NMg8VNUdbaeclfaRaZa8XNa8:a81NMg8WNUdbaeaRaca8XNana81NMg8XNUdbaecxfaRaJa8VNa9ea8WNa8YaTa8XNMMMg8YNUdbaRa8Va8WNNa8ZMh8ZaRa8Va8XNNa8UMh8UaRa8Wa8XNNa8SMh8SaRa8Ya8YNNaUMhUaRa8Va8YNNa87Mh87aRa8Wa8YNNa85Mh85aRa8Xa8YNNa83Mh83aRa8Va8VNNa86Mh86aRa8Wa8WNNaBMhBaRa8Xa8XNNa80Mh80aOclfhOaCclfhCaAclfhAaeczfheaQcufgQmbkagahc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyagaLc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyaga8Ac8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdya8Ra8JcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8RaDcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8Ra8McltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbkaYcifgYad6mbkkcbhAdndnamcwGgSmbJbbbbh86cbh9hcbh9icbh6xekcbh9ha3cbyd;y:L:cjbHjjjjbbh6asc:Cefasyd;8egecdtfa6BdbasaecefBd;8ecua6alabadaHz:fjjjbgCcltaCcjjjjiGEcbyd;y:L:cjbHjjjjbbh9iasc:Cefasyd;8egecdtfa9iBdbasaecefBd;8ea9iaCa6a8Kalz:gjjjbJFFuuh86aCTmba9iheaChOinaeIdbgRa86a86aR9EEh86aeclfheaOcufgOmbkaCh9hkdnalTmbaKclfheaKydbhCa5hOalhQcbhAincbaeydbgLaC9RaORbbcpeGEaAfhAaOcefhOaeclfheaLhCaQcufgQmbkaAce4hAkcuadaA9Rcifg9kcx2a9kc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh0asc:Cefasyd;8egecdtfa0BdbasaecefBd;8ecua9kcdta9kcFFFFi0Ecbyd;y:L:cjbHjjjjbbh9masc:Cefasyd;8egecdtfa9mBdbasaecefBd;8ea3cbyd;y:L:cjbHjjjjbbh9nasc:Cefasyd;8egecdtfa9nBdbasaecefBd;8ealcbyd;y:L:cjbHjjjjbbh9oasc:Cefasyd;8egecdtfa9oBdbasaecefBd;8eaxaxNayJbbjZamclGEg9pa9pN:vh87JbbbbhUdnadak9nmbdna9kci6mbamcjdGh9qaaclth9ra0cwfh9sJbbbbh85JbbbbhUinascNefabadalaHz:cjjjbabh8Acbh3cbh9tinaba9tcdtfh8McbheindnaHa8AaefydbgAcdtghfydbgCaHa8Maec:W:G:cjbfydbcdtfydbgOcdtg8JfydbgQSmba5aOfRbbgYco2a5aAfRbbgLfRb;a:G:cjbg8LaLco2aYfgDRb;a:G:cjbg9cVcFeGTmbdnaQaC9nmbaDRb;W:G:cjbcFeGmekdnaLcufcFeGce0mbaYTmba8EahfydbaO9hmekdnaLTmbaYcufcFeGce0mba8Fa8JfydbaA9hmeka0a3cx2fgCaOaAa9ccFeGgQEBdlaCaAaOaQEBdbaCaQa8LGcb9hBdwa3cefh3kaeclfgecx9hmbkdna9tcifg9tad9pmba8Acxfh8Aa3cifa9k9nmekka3TmdcbhDinaIaHa0aDcx2fghydbgLcdtgCfydbg8Jc8S2fgeIdwa8KahydlgYcx2fgOIdwg8WNaeIdzaOIdbg8XNaeIdaMgRaRMMa8WNaeIdlaOIdlg8YNaeIdCa8WNaeId3MgRaRMMa8YNaeIdba8XNaeIdxa8YNaeIdKMgRaRMMa8XNaeId8KMMM:lhRJbbbbJbbjZaeIdyg8V:va8VJbbbb9BEh8Vdndnahydwg8MmbJFFuuhBxekJbbbbJbbjZaIaHaYcdtfydbc8S2fgeIdyg81:va81Jbbbb9BEaeIdwa8KaLcx2fgOIdwg81NaeIdzaOIdbg80NaeIdaMgBaBMMa81NaeIdlaOIdlgBNaeIdCa81NaeId3Mg81a81MMaBNaeIdba80NaeIdxaBNaeIdKMg81a81MMa80NaeId8KMMM:lNhBka8VaRNh80dnaaTmbagaLc8S2fgAIdwa8WNaAIdza8XNaAIdaMgRaRMMa8WNaAIdla8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaYaa2gQcdtfhOa8RaLaa2g8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaYc8S2fgAIdwa8KaLcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8AcdtfhOa8RaQcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBdndndna5aLfRbbc9:fPibeedkdna8Fa8Ea8EaCfydbaYSEaXaCfydbgQcdtfydbgCcu9hmbaXaYcdtfydbhCkagaQc8S2fgAIdwa8KaCcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaCaa2g8AcdtfhOa8RaQaa2g8JcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaCc8S2fgAIdwa8KaQcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8JcdtfhOa8Ra8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBxdkaXaCfydbgCaLSmbaHaYcdtfydbh8Aindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8ASmekdna8FaQfydbgecuSmbaHaecdtfydba8ASmekaYhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbka80aR:lgRa81aRa819DEaRa9qEMh80aXaQfydbgCaL9hmbkkdna5aYfRbbgeciSmbaecl9hmeka8MTmbaXaYcdtfydbgCaYSmbindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8JSmekdna8FaQfydbgecuSmbaHaecdtfydba8JSmekaLhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaBaR:lgRa81aRa819DEaRa9qEMhBaXaQfydbgCaY9hmbkkahaBa80aBa809DgeEUdwahaLaYaea8Mcb9hGgeEBdlahaYaLaeEBdbaDcefgDa39hmbkascjdfcbcj;qbz:xjjjb8Aa9shea3hOinascjdfaeydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbcefBdbaecxfheaOcufgOmbkcbhecbhOinascjdfaefgAydbhCaAaOBdbaCaOfhOaeclfgecj;qb9hmbkcbhea9shOinascjdfaOydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbgAcefBdba9maAcdtfaeBdbaOcxfhOa3aecefge9hmbkadak9RgAci9Uh9udnalTmbcbhea9nhOinaOaeBdbaOclfhOalaecefge9hmbkkcbh9va9ocbalz:xjjjbh9caAcO9Uh9wa9uce4h9tcbh8Lcbh8Mdnina0a9ma8Mcdtfydbcx2fg8JIdwgRa879Emea8La9u9pmeJFFuuh8Vdna9ta39pmba0a9ma9tcdtfydbcx2fIdwJbb;aZNh8VkdnaRa8V9ETmbaRaU9ETmba8La9w0mdkdna9caHa8JydlgDcdtg9xfg8AydbgAfg9yRbba9caHa8Jydbghcdtg9zfydbgefg9ARbbVmba5ahfRbbh9BdndnaKaecdtfgOclfydbgCaOydbgOSmbaCaO9RhCa8KaAcx2fhLa8Kaecx2fhYaEaOcitfheindna9naeydbcdtfydbgOaASmba9naeclfydbcdtfydbgQaASmbaOaQSmba8KaQcx2fgQIdba8KaOcx2fgOIdbg8W:tgRaYIdlaOIdlg8X:tg80NaQIdla8X:tg8VaYIdba8W:tgBN:tg8YaRaLIdla8X:tg8SNa8VaLIdba8W:tg8UN:tg8XNa8VaYIdwaOIdwg81:tg8ZNaQIdwa81:tg8Wa80N:tg80a8VaLIdwa81:tg83Na8Wa8SN:tg8VNa8WaBNaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmikaecwfheaCcufgCmbkkdndna9Bc99fcFeGce0mba9na9zfaDBdbaXa9zfydbgeahSmeina8AydbhAdndna8EaecdtgOfydbgecuSmbaHaecdtfydbaASmekdna8FaOfydbgecuSmbaHaecdtfydbaASmekaDheka9naOfaeBdbaXaOfydbgeah9hmbxdkkdndna9BcFeGcdSmbaDhexekdna8Fa8Ea8Ea9zfydbaDSEaXa9zfydbghcdtfydbgecu9hmbaXa9xfydbheka9na9zfaDBdbka9nahcdtfaeBdbka9Ace86bba9yce86bba8JIdwgRaUaUaR9DEhUa9vcefh9vcecda9BcFeGceSEa8Lfh8Lxeka9tcefh9tka8Mcefg8Ma39hmbkka9vTmddnalTmbcbhLcbhhindna9nahcdtgefydbgAahSmbaHaAcdtfydbh8AdnahaHaefydb9hg8JmbaIa8Ac8S2fgeaIahc8S2fgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya8NTmba8Na8Acltfgea8NahcltfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxkaaTmbagaAc8S2fgeagahc8S2g8MfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya9raA2hYa8RhOaahCinaOaYfgeaOaLfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8JmbJbbbbJbbjZaIa8MfgeIdygR:vaRJbbbb9BEaeIdwa8Ka8Acx2fgOIdwgRNaeIdzaOIdbg8VNaeIdaMg8Wa8WMMaRNaeIdlaOIdlg8WNaeIdCaRNaeId3MgRaRMMa8WNaeIdba8VNaeIdxa8WNaeIdKMgRaRMMa8VNaeId8KMMM:lNgRa85a85aR9DEh85kaLa9rfhLahcefghal9hmbkcbhOa8EheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8EaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkcbhOa8FheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8FaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkka85aUaaEh85cbhOabhecbhAindnaHa9naeydbcdtfydbgLcdtfydbgCaHa9naeclfydbcdtfydbgYcdtfydbgQSmbaCaHa9naecwfydbcdtfydbg8AcdtfydbghSmbaQahSmbabaOcdtfgCaLBdbaCcwfa8ABdbaCclfaYBdbaOcifhOkaecxfheaAcifgAad6mbkdndnaSmbaOhdxekdnaOak0mbaOhdxekdna86a859FmbaOhdxekJFFuuh86cbhdabhecbhAindna9ia6aeydbgCcdtfydbcdtfIdbgRa859ETmbaeclf8Pdbh9CabadcdtfgQaCBdbaQclfa9C83dbaRa86a86aR9EEh86adcifhdkaecxfheaAcifgAaO6mbkkadak0mbxdkkascNefabadalaHz:cjjjbkdndnadak0mbadhYxekdnaSmbadhYxekdna86a879FmbadhYxekcehQina86Jbb;aZNgRa87aRa879DEh8WJbbbbhRdna9hTmba9ihea9hhOinaeIdbg8VaRa8Va8W9FEaRa8VaR9EEhRaeclfheaOcufgOmbkkJFFuuh86cbhYabhecbhOindna9ia6aeydbgAcdtfydbcdtfIdbg8Va8W9ETmbaeclf8Pdbh9CabaYcdtfgCaABdbaCclfa9C83dba8Va86a86a8V9EEh86aYcifhYkaecxfheaOcifgOad6mbkdnaQaYad9hVceGmbadhYxdkaRaUaUaR9DEhUaYak9nmecbhQaYhda86a879FmbkkdnamcjjjjdGTmba9ocbalz:xjjjbh8AdnaYTmbabheaYhOina8AaeydbgAfce86bba8AaHaAcdtfydbfce86bbaeclfheaOcufgOmbkkascNefabaYalaHz:cjjjbdndnalTmbcbhCindna8AaCfRbbTmbdna5aCfRbbPlbeebekdnaHaCcdtgLfydbgeaCSmba8KaCcx2fgOa8Kaecx2fgeydwBdwaOae8Pdb83dbxekaIaCc8S2fgQIdygnanJL:3;rUNgRMh87aQIdwgxaRMh8SaQIdlg9DaRMh8UaQIdbg9EaRMh81aQIdag9FaRa8KaCcx2fg8JIdwg88N:th8ZaQId3g9GaRa8JIdlg89N:th83aQIdKg9Ha8JIdbg8:aRN:th80JbbbbhZaQIdCg9IJbbbbMh85aQIdzg9JJbbbbMhBaQIdxg9KJbbbbMh86dndnaaTmbaChAinJbbbba87agaAc8S2fgOIdygR:vaRJbbbb9BEhRa8RaAaa2cltfheaOIdaa87Na8ZMh8ZaOId3a87Na83Mh83aOIdKa87Na80Mh80aOIdCa87Na85Mh85aOIdza87NaBMhBaOIdxa87Na86Mh86aOIdwa87Na8SMh8SaOIdla87Na8UMh8UaOIdba87Na81Mh81aahOina8ZaecwfIdbg8VaecxfIdbg8YNaRN:th8Za83aeclfIdbg8Wa8YNaRN:th83a85a8Wa8VNaRN:th85a81aeIdbg8Xa8XNaRN:th81a80a8Xa8YNaRN:th80aBa8Xa8VNaRN:thBa86a8Xa8WNaRN:th86a8Sa8Va8VNaRN:th8Sa8Ua8Wa8WNaRN:th8UaeczfheaOcufgOmbkaXaAcdtfydbgAaC9hmbka8NTmba8NaCcltfgeIdxhTaeIdwhcaeIdlhJaeIdbhRxekJbbbbhTJbbbbhcJbbbbhJJbbbbhRkaBa81:vg8Wa80Na8Z:ta85aBa86a81:vg8VN:tg8Za8Ua86a8VN:tg8Y:vg8Xa8Va80Na83:tg8UN:th83acaRa8WN:taJaRa8VN:tg86a8XN:tg85a8SaBa8WN:ta8Za8XN:tgB:vg8S:mh8Za86a8Y:vgc:mhJdnJbbbbaRaRa81:vg9eN:ta86acN:ta85a8SN:tg86:la87J:983:g81NgR9ETmba8Za83NaJa8UNa9ea80NaT:tMMa86:vhZka81:laR9ETmba8Y:laR9ETmbaB:laR9ETmba9e:maZNa8W:ma8ZaZNa83aB:vMgBNa8V:maJaZNa8X:maBNa8Ua8Y:vMMg85Na80:ma81:vMMMh87aKaLfgeclfydbgOaeydbge9RhhaEaecitfhLJbbbbhRdnaOaeSg8MmbJbbbbhRaLheahhAina8Kaeclfydbcx2fgOIdwa88:tg8Va8VNaOIdba8::tg8Va8VNaOIdla89:tg8Va8VNMMg8Va8Kaeydbcx2fgOIdwa88:tg8Wa8WNaOIdba8::tg8Wa8WNaOIdla89:tg8Wa8WNMMg8WaRaRa8W9DEgRaRa8V9DEhRaecwfheaAcufgAmbkaR:rgRaRNhRkaBa88:tg8Va8VNa87a8::tg8Va8VNa85a89:tg8Va8VNMMaR9EmbaQId8KhZdna8Mmbina8KaLclfydbcx2fgeIdba8KaLydbcx2fgOIdbg8W:tgRa89aOIdlg8X:tg80NaeIdla8X:tg8Va8:a8W:tg86N:tg8YaRa85a8X:tg8SNa8Va87a8W:tg8UN:tg8XNa8Va88aOIdwg81:tg8ZNaeIdwa81:tg8Wa80N:tg80a8VaBa81:tg83Na8Wa8SN:tg8VNa8Wa86NaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmdaLcwfhLahcufghmbkkJbbbbJbbjZan:vanJbbbb9BEgRaxaBNa9Ja87Na9FMg8Va8VMMaBNa9Da85Na9IaBNa9GMg8Va8VMMa85Na9Ea87Na9Ka85Na9HMg8Va8VMMa87NaZMMM:lNaRaxa88Na9Ja8:Na9FMg8Va8VMMa88Na9Da89Na9Ia88Na9GMg8Va8VMMa89Na9Ea8:Na9Ka89Na9HMg8Va8VMMa8:NaZMMM:lNJbb;aZNJ:983:g81M9Emba8JaBUdwa8Ja85Udla8Ja87UdbkaCcefgCal9hmbkdnaambcbhaxdkcbhQindna8AaQfRbbTmbaHaQcdtgefydbaQ9hmba5aQfhhaXaefh8Ja8KaQcx2fhAa8PaQaa2cdtfh8McbhEincuhCdnahRbbc99fcFeGce0mbaQhCa8JydbgeaQSmba8PaEcdtgOfhLa8MaOfIdbhRaQhCinaChOcuhCdnaLaeaa2cdtfIdbaR9CmbaOcuSmbaOhCagaec8S2fIdyagaOc8S2fIdy9ETmbaehCkaXaecdtfydbgeaQ9hmbkka8PaEcdtfhLa8RaEcltfhKaQheinaLaeaa2cdtfJbbbbJbbjZagaeaCaCcuSEgOc8S2fIdygR:vaRJbbbb9BEaKaOaa2cltfgOIdwaAIdwNaOIdbaAIdbNaOIdlaAIdlNMMaOIdxMNUdbaXaecdtfydbgeaQ9hmbkaEcefgEaa9hmbkkaQcefgQal9hmbxdkkaambcbhakaiavaoarawaaala8Ka8Pazasayasc1efa5a8Aaqz:hjjjbkdnamcjjjjlGTmbazmbaYTmbabhecbhLina5aeydbgAfRbbc3thQaecwfgXydbhHcjjjj94hCdna8EaAcdtgEfydbaeclfgKydbgOSmbcjjjj94cba8FaOcdtfydbaASEhCkaeaQaCVaAVBdba5aOfRbbc3thacjjjj94hCcjjjj94hQdna8EaOcdtfydbaHSmbcjjjj94cba8FaHcdtfydbaOSEhQkaKaaaQVaOVBdba5aHfRbbc3thOdna8EaHcdtfydbaASmbcjjjj94cba8FaEfydbaHSEhCkaXaOaCVaHVBdbaecxfheaLcifgLaY6mbkkdnazTmbaYTmbaYheinabazabydbcdtfydbBdbabclfhbaecufgembkkdnaPTmbaPa9paU:rNUdbkdnasyd;8egHTmbaHcdtasc:Ceffc98fheinaeydbcbyd;C:L:cjbH:bjjjbbaec98fheaHcufgHmbkkascj;sbf8KjjjjbaYk;Yieouabydlhvabydbclfcbaicdtz:xjjjbhoadci9UhrdnadTmbdnalTmbaehwadhDinaoalawydbcdtfydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbxdkkaehwadhDinaoawydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbkkdnaiTmbcbhDaohwinawydbhqawaDBdbawclfhwaqaDfhDaicufgimbkkdnadci6mbinaecwfydbhwaeclfydbhDaeydbhidnalTmbalawcdtfydbhwalaDcdtfydbhDalaicdtfydbhikavaoaicdtfgqydbcitfaDBdbavaqydbcitfawBdlaqaqydbcefBdbavaoaDcdtfgqydbcitfawBdbavaqydbcitfaiBdlaqaqydbcefBdbavaoawcdtfgwydbcitfaiBdbavawydbcitfaDBdlawawydbcefBdbaecxfhearcufgrmbkkabydbcbBdbk:todDue99aicd4aifhrcehwinawgDcethwaDar6mbkcuaDcdtgraDcFFFFi0Ecbyd;y:L:cjbHjjjjbbhwaoaoyd9GgqcefBd9GaoaqcdtfawBdbawcFearz:xjjjbhkdnaiTmbalcd4hlaDcufhxcbhminamhDdnavTmbavamcdtfydbhDkcbadaDal2cdtfgDydlgwawcjjjj94SEgwcH4aw7c:F:b:DD2cbaDydbgwawcjjjj94SEgwcH4aw7c;D;O:B8J27cbaDydwgDaDcjjjj94SEgDcH4aD7c:3F;N8N27axGhwamcdthPdndndnavTmbakawcdtfgrydbgDcuSmeadavaPfydbal2cdtfgsIdbhzcehqinaqhrdnadavaDcdtfydbal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmlkarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbxdkkakawcdtfgrydbgDcuSmbadamal2cdtfgsIdbhzcehqinaqhrdnadaDal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmikarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbkkaramBdbamhDkabaPfaDBdbamcefgmai9hmbkkakcbyd;C:L:cjbH:bjjjbbaoaoyd9GcufBd9GdnaeTmbaiTmbcbhDaehwinawaDBdbawclfhwaiaDcefgD9hmbkcbhDaehwindnaDabydbgrSmbawaearcdtfgrydbBdbaraDBdbkabclfhbawclfhwaiaDcefgD9hmbkkk;:odvuv998Jjjjjbca9Rgocbyd1:G:cjbBdKaocb8Pdj:G:cjb83izaocbydN:G:cjbBdwaocb8Pd:m:G:cjb83ibdnadTmbaicd4hrdnabmbdnalTmbcbhwinaealawcdtfydbar2cdtfhDcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxikkarcdthwcbhDincbhiinaoczfaifgqaeaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaeawfheaDcefgDad9hmbxdkkdnalTmbcbhwinabawcx2fgiaealawcdtfydbar2cdtfgDIdbUdbaiaDIdlUdlaiaDIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxdkkarcdthlcbhwaehDinabawcx2fgiaeawar2cdtfgqIdbUdbaiaqIdlUdlaiaqIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaDalfhDawcefgwad9hmbkkJbbbbaoIdbaoIdzgx:tgkakJbbbb9DEgkaoIdlaoIdCgm:tgPaPak9DEgkaoIdwaoIdKgP:tgsasak9DEhsdnabTmbadTmbJbbbbJbbjZas:vasJbbbb9BEhkinabakabIdbax:tNUdbabclfgoakaoIdbam:tNUdbabcwfgoakaoIdbaP:tNUdbabcxfhbadcufgdmbkkdnavTmbavaPUdwavamUdlavaxUdbkask:WlewudnaeTmbcbhvabhoinaoavBdbaoclfhoaeavcefgv9hmbkkdnaiTmbcbhrinadarcdtfhwcbhDinalawaDcdtgvyd:G:G:cjbcdtfydbcdtfydbhodnalawavfydbcdtfydbgqabaqcdtfgkydbgvSmbinakabavgqcdtfgxydbgvBdbaxhkaqav9hmbkkdnaoabaocdtfgkydbgvSmbinakabavgocdtfgxydbgvBdbaxhkaoav9hmbkkdnaqaoSmbabaqaoaqao0Ecdtfaqaoaqao6EBdbkaDcefgDci9hmbkarcifgrai6mbkkdnaembcbskcbhxindnalaxcdtgvfydbax9hmbaxhodnaxabavfgDydbgvSmbaDhqinaqabavgocdtfgkydbgvBdbakhqaoav9hmbkkaDaoBdbkaxcefgxae9hmbkcbhkabhvcbhoindndnaoalydbgq9hmbdnaoavydbgq9hmbavakBdbakcefhkxdkavabaqcdtfydbBdbxekavabaqcdtfydbBdbkalclfhlavclfhvaeaocefgo9hmbkakk;jiilud99euabcbaecltz:xjjjbhvdnalTmbadhoaihralhwinarcwfIdbhDarclfIdbhqavaoydbcltfgkarIdbakIdbMUdbakaqakIdlMUdlakaDakIdwMUdwakakIdxJbbjZMUdxaoclfhoarcxfhrawcufgwmbkkdnaeTmbavhkaehrinakcxfgoIdbhDaocbBdbakakIdbJbbbbJbbjZaD:vaDJbbbb9BEgDNUdbakclfgoaDaoIdbNUdbakcwfgoaDaoIdbNUdbakczfhkarcufgrmbkkdnalTmbinavadydbcltfgkaicwfIdbakIdw:tgDaDNaiIdbakIdb:tgDaDNaiclfIdbakIdl:tgDaDNMMgDakIdxgqaqaD9DEUdxadclfhdaicxfhialcufglmbkkdnaeTmbavcxfhkinabakIdbUdbakczfhkabclfhbaecufgembkkk:moerudnaoTmbaecd4hzdnavTmbaicd4hHavcdthOcbhAindnaPaAfRbbTmbaAhednaDTmbaDaAcdtfydbhekdnasTmbasaefRbbceGmekdnamaAfRbbcvSmbabaeaz2cdtfgiaraAcx2fgCIdbakNaxIdbMUdbaiaCIdlakNaxIdlMUdlaiaCIdwakNaxIdwMUdwkadaeaH2cdtfhXaqheawhiavhCinaXaeydbcdtgQfaiIdbalaQfIdb:vUdbaeclfheaiclfhiaCcufgCmbkkawaOfhwaAcefgAao9hmbxdkkdnasmbcbheaDhiindnaPaefRbbTmbaehCdnaDTmbaiydbhCkamaefRbbcvSmbabaCaz2cdtfgCarIdbakNaxIdbMUdbaCarclfIdbakNaxIdlMUdlaCarcwfIdbakNaxIdwMUdwkaiclfhiarcxfhraoaecefge9hmbxdkkdnaDTmbindnaPRbbTmbasaDydbgefRbbceGmbamRbbcvSmbabaeaz2cdtfgearIdbakNaxIdbMUdbaearclfIdbakNaxIdlMUdlaearcwfIdbakNaxIdwMUdwkaPcefhPaDclfhDamcefhmarcxfhraocufgombxdkkazcdthicbheindnaPaefRbbTmbasaefRbbceGmbamaefRbbcvSmbabarIdbakNaxIdbMUdbabclfarclfIdbakNaxIdlMUdbabcwfarcwfIdbakNaxIdwMUdbkarcxfhrabaifhbaoaecefge9hmbkkk8MbabaeadaialavcbcbcbcbcbaoarawaDz:bjjjbk8MbabaeadaialavaoarawaDaqakaxamaPz:bjjjbkRbababaeadaialavaoarawaDaqakaxcjjjjdVamz:bjjjbk:vgoque99due99duq998Jjjjjbc;Wb9Rgq8Kjjjjbcbhkaqcxfcbc;Kbz:xjjjb8Aaqcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgxBdxaqceBd2axaialavcbcbz:ejjjb8AaqcualcdtalcFFFFi0Egmcbyd;y:L:cjbHjjjjbbgiBdzaqcdBd2dndnJFF959eJbbjZawJbbjZawJbbjZ9DE:vawJ9VO:d869DEgw:lJbbb9p9DTmbaw:OhPxekcjjjj94hPkadci9Uhsarco9UhzdndnaombaPcd9imekdnalTmbaPcuf:YhwdnaoTmbcbhvaihHaxhOindndnaoavfRbbceGTmbavcjjjjlVhAxekdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHaOcxfhOalavcefgv9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkadTmbcbhkaehvcbhOinakaiavclfydbcdtfydbgHaiavcwfydbcdtfydbgA9haiavydbcdtfydbgXaH9haXaA9hGGfhkavcxfhvaOcifgOad6mbkkarci9UhQdndnaz:Z:rJbbbZMgw:lJbbb9p9DTmbaw:Ohvxekcjjjj94hvkaQ:ZhLcbhKc:bwhzdninakaQ9pmeazaP9Rcd9imeavazcufgOavaO9iEaPcefavaP9kEhYdnalTmbaYcuf:YhwdnaoTmbcbhOaihHaxhvindndnaoaOfRbbceGTmbaOcjjjjlVhAxekdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHavcxfhvalaOcefgO9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkcbhOdnadTmbaehvcbhHinaOaiavclfydbcdtfydbgAaiavcwfydbcdtfydbgX9haiavydbcdtfydbgraA9haraX9hGGfhOavcxfhvaHcifgHad6mbkkdnas:ZgCaL:taY:Ygwaz:Y:tg8ANak:ZgEaO:Zg3:tNaEaL:tawaP:Y:tg5Na3aC:tNMg8EJbbbb9BmbaCaE:ta5a8Aa3aL:tNNNa8E:vawMhwkdndnaOaQ0mbaOhkaYhPxekaOhsaYhzkdndnaKcl0mbdnawJbbbZMgw:lJbbb9p9DTmbaw:Ohvxdkcjjjj94hvxekaPazfcd9ThvkaKcefgKcs9hmbkkdndndnakmbJbbjZhwcbhOcdhvaDmexdkalcd4alfhHcehOinaOgvcethOavaH6mbkaqcuavcdtavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgYBdCaqciBd2aqamcbyd;y:L:cjbHjjjjbbgzBdKaqclBd2dnalTmbaPcuf:YhwdnaoTmbcbhOaihAaxhHindndnaoaOfRbbceGTmbaOcjjjjlVhXxekdndnaHclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqthXdndnaHcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarVhXdndnaHIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarcCtVhXkaAaXBdbaAclfhAaHcxfhHalaOcefgO9hmbxdkkaxhOaihHalhAindndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcCthXdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkarcqtaXVhXdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaHaXarVBdbaOcxfhOaHclfhHaAcufgAmbkkaqcuaYavazaialz:mjjjbgXc8S2gvaXc;D;O;f8U0Ecbyd;y:L:cjbHjjjjbbgiBd3aqcvBd2aicbavz:xjjjbhOdnadTmbcbhraehiinaxaiclfydbgocx2fgvIdbaxaiydbgPcx2fgHIdbg3:tgCaxaicwfydbgYcx2fgAIdlaHIdlg8A:tgwNavIdla8A:tgEaAIdba3:tg8EN:tgLaLNaEaAIdwaHIdwg5:tg8FNavIdwa5:tgEawN:tgwawNaEa8ENaCa8FN:tgCaCNMMg8E:rhEJbbnnJbbjZazaPcdtfydbgvazaocdtfydbgASavazaYcdtfydbgoSGgHEh8Fdna8EJbbbb9ETmbaLaE:vhLaCaE:vhCawaE:vhwkaOavc8S2fgvavIdbawa8FaE:rNgEawNNg8FMUdbavaCaEaCNgaNghavIdlMUdlavaLaEaLNg8ENggavIdwMUdwavawaaNgaavIdxMUdxava8EawNg8JavIdzMUdzavaCa8ENg8EavIdCMUdCavawaEaLa5Nawa3Na8AaCNMM:mg8ANg3NgwavIdKMUdKavaCa3NgCavId3MUd3avaLa3NgLavIdaMUdaava3a8ANg3avId8KMUd8KavaEavIdyMUdydnaHmbaOaAc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdyaOaoc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdykaicxfhiarcifgrad6mbkkcbhAaqcuaXcdtgvaXcFFFFi0Egicbyd;y:L:cjbHjjjjbbgHBdaaqcoBd2aqaicbyd;y:L:cjbHjjjjbbgiBd8KaqcrBd2aHcFeavz:xjjjbhPdnalTmbazhHinJbbbbJbbjZaOaHydbgrc8S2fgvIdygw:vawJbbbb9BEavIdwaxcwfIdbgwNavIdzaxIdbgCNavIdaMgLaLMMawNavIdlaxclfIdbgLNavIdCawNavId3MgwawMMaLNavIdbaCNavIdxaLNavIdKMgwawMMaCNavId8KMMM:lNhwdndnaParcdtgvfgrydbcuSmbaiavfIdbaw9ETmekaraABdbaiavfawUdbkaHclfhHaxcxfhxalaAcefgA9hmbkkdndnaXmbJbbbbhwxekJbbbbhwinaiIdbgCawawaC9DEhwaiclfhiaXcufgXmbkaw:rhwkakcd4akfhOcehiinaigvcethiavaO6mbkcbhOaqcuavcdtgiavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgHBdyaHcFeaiz:xjjjbhXdnadTmbavcufhrcbhkcbhxindnazaeaxcdtfgvydbcdtfydbgiazavclfydbcdtfydbgOSmbaiazavcwfydbcdtfydbgvSmbaOavSmbaPavcdtfydbhAdndnaPaOcdtfydbgvaPaicdtfydbgi9pmbavaA9pmbaAhlaihoavhAxekdnaAai9pmbaAav9pmbaihlavhoxekavhlaAhoaihAkabakcx2fgvaABdbavcwfaoBdbavclfalBdbdnaXaoc:3F;N8N2alc:F:b:DD27aAc;D;O:B8J27arGgOcdtfgvydbgicuSmbcehHinaHhvdnabaicx2fgiydbaA9hmbaiydlal9hmbaiydwaoSmikavcefhHaXaOavfarGgOcdtfgvydbgicu9hmbkkavakBdbakcefhkkaxcifgxad6mbkakci2hOkcwhvaDTmekaDawUdbkavcdthvaqcxfc98fhiinaiavfydbcbyd;C:L:cjbH:bjjjbbavc98fgvmbkaqc;Wbf8KjjjjbaOk:0iewuabcFeaecdtz:xjjjbhbdnalmbcbskaecufhvdndnaiTmbcbhocbhrindndndnabaiarcdtgwfydbgDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbceheinaiaxcdtgxfydbaDSmdaqaefhxaecefheabaxavGgqcdtfgkydbgxcu9hmbkkakarBdbaoheaocefhoxekadaxfydbhekadawfaeBdbarcefgral9hmbxdkkcbhocbhDindnabaDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbaxaDSmbceheinabaqaefavGgqcdtfgkydbgxcuSmeaecefheaxaD9hmbkkdndnaxcu9hmbakaDBdbaoheaocefhoxekadaxcdtfydbhekadaDcdtfaeBdbaDcefgDal9hmbkkaok:3ldrue9:8Jjjjjbc;Wb9Rgr8Kjjjjbcbhwarcxfcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkarcualcdtalcFFFFi0EgDcbyd;y:L:cjbHjjjjbbgqBdxarceBd2aqcbaialavcbarcxfz:djjjbcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbhkarcxfaryd2gxcdtfakBdbaraxcefgmBd2akaialavcbcbz:ejjjb8AarcxfamcdtfaDcbyd;y:L:cjbHjjjjbbgiBdbaraxcdfgvBd2arcxfavcdtfcuaialaeadaqz:fjjjbgecltaecjjjjiGEcbyd;y:L:cjbHjjjjbbgqBdbaqaeaiakalz:gjjjbaxcifhkdnadTmbaoaoNhocbhwabhlcbheindnaqaialydbgvcdtfydbcdtfIdbao9ETmbalclf8PdbhPabawcdtfgDavBdbaDclfaP83dbawcifhwkalcxfhlaecifgead6mbkkdnakTmbaxcdtarcxffcwfhlinalydbcbyd;C:L:cjbH:bjjjbbalc98fhlakcufgkmbkkarc;Wbf8Kjjjjbawk;lOoDud99oue99vuv998Jjjjjbc;Wb9Rgw8KjjjjbdndnarmbcbhDxekawcxfcbc;Kbz:xjjjb8Aawcuadcx2adc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgqBdxawceBd2aqaeadaicbcbz:ejjjb8AawcuadcdtadcFFFFi0Egkcbyd;y:L:cjbHjjjjbbgxBdzawcdBd2adcd4adfhecehiinaigmcethiamae6mbkcbhPawcuamcdtgsamcFFFFi0Ecbyd;y:L:cjbHjjjjbbgzBdCawciBd2dndnar:ZgH:rJbbbZMgO:lJbbb9p9DTmbaO:Ohixekcjjjj94hikamcufhAc:bwhCcbhXadhQcbhLinaiaCcufgeaiae9iEaPcefaiaP9kEhDdndnadTmbaDcuf:YhOaqhiaxheadhKindndnaiIdbaONJbbbZMgY:lJbbb9p9DTmbaY:Oh8Axekcjjjj94h8Aka8AcCth8AdndnaiclfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaEcqta8AVh8AdndnaicwfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaea8AaEVBdbaicxfhiaeclfheaKcufgKmbkazcFeasz:xjjjbh3cbh5cbh8Eindna3axa8Ecdtfydbg8Acm4a8A7c:v;t;h;Ev2gics4ai7aAGgKcdtfgEydbgecuSmbaea8ASmbcehiina3aKaifaAGgKcdtfgEydbgecuSmeaicefhiaea8A9hmbkkaEa8ABdba5aecuSfh5a8Ecefg8Ead9hmbxdkkazcFeasz:xjjjb8Acbh5kdnaQ:ZgYaH:taD:YgOaC:Y:tg8FNaX:Zgaa5:Zgh:tNaaaH:taOaP:Y:tggNahaY:tNMg8JJbbbb9BmbaYaa:taga8FahaH:tNNNa8J:vaOMhOkaPaDa5ar0geEhPaXa5aeEhXdna5arSmbaDaCaeEgCaP9Rcd9imbdndnaLcl0mbdnaOJbbbZMgO:lJbbb9p9DTmbaO:Ohixdkcjjjj94hixekaPaCfcd9Thika5aQaeEhQaLcefgLcs9hmekkdndnaXmbcihicbhDxekawakcbyd;y:L:cjbHjjjjbbg8ABdKawclBd2aPcuf:YhYdnadTmbaqhiaxheadhKindndnaiIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:OhExekcjjjj94hEkaEcCthEdndnaiclfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3ka3cqtaEVhEdndnaicwfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3kaeaEa3VBdbaicxfhiaeclfheaKcufgKmbkkawcuazama8Aaxadz:mjjjbgDc32giaDc;j:KM;jb0Ecbyd;y:L:cjbHjjjjbbgeBd3awcvBd2aecbaiz:xjjjbh3avcd4hxdnadTmbdnalTmbaxcdth8Ea8AhEaqhealhKadhAina3aEydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaKIdbaiIdxMUdxaiaKclfIdbaiIdzMUdzaiaKcwfIdbaiIdCMUdCaiaiIdKJbbjZMUdKaEclfhEaecxfheaKa8EfhKaAcufgAmbxdkka8AhKaqheadhEina3aKydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaiIdxJbbbbMUdxaiaiIdzJbbbbMUdzaiaiIdCJbbbbMUdCaiaiIdKJbbjZMUdKaKclfhKaecxfheaEcufgEmbkkdnaDTmba3hiaDheinaiaiIdbJbbbbJbbjZaicKfIdbgO:vaOJbbbb9BEgONUdbaiclfgKaOaKIdbNUdbaicwfgKaOaKIdbNUdbaicxfgKaOaKIdbNUdbaiczfgKaOaKIdbNUdbaicCfgKaOaKIdbNUdbaic3fhiaecufgembkkcbhEawcuaDcdtgCaDcFFFFi0Egicbyd;y:L:cjbHjjjjbbgeBdaawcoBd2awaicbyd;y:L:cjbHjjjjbbg8EBd8KaecFeaCz:xjjjbh5dnadTmbaoJbbjZJbbjZaY:vaPceSENgOaONhYaxcdthxalheinaYaecN:H:cjbalEgKIdwa3a8AydbgAc32fgiIdC:tgOaONaKIdbaiIdx:tgOaONaKIdlaiIdz:tgOaONMMNaqcwfIdbaiIdw:tgOaONaqIdbaiIdb:tgOaONaqclfIdbaiIdl:tgOaONMMMhOdndna5aAcdtgifgKydbcuSmba8EaifIdbaO9ETmekaKaEBdba8EaifaOUdbka8Aclfh8AaqcxfhqaeaxfheadaEcefgE9hmbkkaba5aCz:wjjjb8Acrhikaicdthiawcxfc98fheinaeaifydbcbyd;C:L:cjbH:bjjjbbaic98fgimbkkawc;Wbf8KjjjjbaDk:Pdidui99ducbhi8Jjjjjbca9Rglcbyd1:G:cjbBdKalcb8Pdj:G:cjb83izalcbydN:G:cjbBdwalcb8Pd:m:G:cjb83ibdndnaembJbbjFhvJbbjFhoJbbjFhrxekadcd4cdthwincbhdinalczfadfgDabadfIdbgvaDIdbgoaoav9EEUdbaladfgDavaDIdbgoaoav9DEUdbadclfgdcx9hmbkabawfhbaicefgiae9hmbkalIdwalIdK:thralIdlalIdC:thoalIdbalIdz:thvkJbbbbavavJbbbb9DEgvaoaoav9DEgvararav9DEk:H8Modui99lud99Aus998Jjjjjbcji9RgD8KjjjjbcbhqaDcxfcbc;Kbz:xjjjb8AaDcbBdwaD9cb83ibaDcbyd;i:L:cjbBd1eaDcb8Pd;a:L:cjb83ijeaDcbyd;u:L:cjbBd94aDcb8Pd;m:L:cjb83i9WdndnavmbJbbjFhkJbbjFhxJbbjFhmxekaocd4cdthPalhsincbhzinaDcjefazfgHasazfIdbgkaHIdbgxaxak9EEUdbaDc;WbfazfgHakaHIdbgxaxak9DEUdbazclfgzcx9hmbkasaPfhsaqcefgqav9hmbkaDId94aDId1e:thmaDIdtaDId:ee:thxaDId9WaDIdje:thkkJbbbbhOdnar:YgAJq;x8J88MaA:vJbbbbakakJbbbb9DEgkaxaxak9DEgkamamak9DENgxJbbbb9Bmbarc9:f:Yax:vhOkaDcCfhCaDcxfcxfhXcbhzinaDazfaDcjefazfIdbgkaxaDc;WbfazfIdbak:t:tJbbb:;NMUdbazclfgzcx9hmbkcbhQaDarar2gLar2gzcbyd;y:L:cjbHjjjjbbgHBdxaDceBd2aHcbazz:xjjjbgKcbcbadaialaoaraOaDawz:rjjjbcdhYaDcuaLcdtaLcFFFFi0Eg8Acbyd;y:L:cjbHjjjjbbgEBdzaDcdBd2aDcjefcbarz:xjjjb8Acbh3dnaLTmbdnarcb9kmbaKhzaEhHaLhsincbh3aHcbcuazaDcjefarz:AjjjbEBdbazarfhzaHclfhHascufgsmbxdkkaKhPcbh3cbhvindndnaKavar2faDcjefarz:AjjjbTmbcbhHaPhzarhsinazaHazRbbgqfgHcbaqE86bbazcefhzascufgsmbkaEavcdtfa3BdbaHa3fh3xekaEavcdtfcuBdbkaParfhPavcefgvaL9hmbkkdnabTmbaDcua3cotgza3cFFF8F0Ecbyd;y:L:cjbHjjjjbbgQBdCcihYaDciBd2aQcbazz:xjjjb8AaXhCkdnawceGmbaCa8Acbyd;y:L:cjbHjjjjbbg5BdbaDaYcefgzBd2aDcxfazcdtfaLcbyd;y:L:cjbHjjjjbbgzBdbaDaYcdfgYBd2azcbaLz:xjjjbh8EarcufhXdnarci9imbarc9:fhCararcef2aKfcefh8Aceh8Fina8Far2hPa8AhvcehqindnaEaqaPfcdtfydbcuSmbavhzaChHinazazRbbgscuasE86bbazcefhzaHcufgHmbkkavarfhvaqcefgqaX9hmbka8AaLfh8Aa8Fcefg8FaX9hmbkkarce9imbcbh8Acbhqcbhvina8EaqfhscbhzindnasazfgHRbbmbaHce86bba5a8AcdtfaqazfBdba8Acefh8Akarazcefgz9hmbkaqarfhqavcefgvar9hmbka8ATmbaKcefhaaKc9:fhharc9:fhgarci9ih8Jina8Ea5a8Acufg8Acdtfydbgvfcb86bbavar2hPdna8JmbaEavcdtfydbcuSmbaKaPfhHaghqindnaHcefgzRbbgscFe9hmbaHRbbmbcbhskazas86bbazhHaqcufgqmbkaharavcef2fhzaXhsindnazRbbgHcFe9hmbazcefRbbmbcbhHkazaH86bbazcufhzascufgsce9kmbkkaaaPfh8Kavavar9Ug8Lar29Rh8FcbhCindnaCceScuaCEa8Ffgzce9imbazaX9ombcuaCciSaCcdSEa8LfgHce9imbaHaX9ombaEaHar2azfg8McdtfydbcuSmba8Jmbaaa8Mar2fhzcbhqa8KhsaghvinazazRbbgHcbaHaHcFeSEasRbbEgP86bbascefhsazcefhzaPaH7aqVhqavcufgvmbkaqcFeGTmba8Ea8MfgzRbbmbazce86bba5a8Acdtfa8MBdba8Acefh8AkaCcefgCcl9hmbka8AmbkkdnaQTmbaKaEaQadaialaoaraOaDawz:rjjjba3TmbJbbjZaO:vhkawcjjjjlGhPdnawcdGTmbJbbnnaOaON:vh8NakJbbbZNhyaQhzinazczfgsIdbg8PazcCfIdbgx:vhmazcxfgqIdbgIax:vhAazcwfgvIdbg8Rax:vh8SakazydbgHcFrG:ZNhRakaHcq4cFrG:ZNh8UakaHcC4cFrG:ZNh8VdnaxJ:p;c;188Ng8WazcKfIdbMg8X:laxJ:983:g81Ngx9ETmba8Wazc3fIdbMazc8KfIdbg8Ya8Ya8X:vg8YN:tg8Z:lax9ETmba8WazcafIdbMazcyfIdbg8Wa8Wa8X:vg80N:tazc8SfIdba8Wa8YN:tg8Wa8Wa8Z:vg8WN:tg81:lax9ETmba8PJ:p;c;188NazcUfIdb:ta80a8RJ:p;c;188Nazc8WfIdb:tg8PN:ta8WaIJ:p;c;188Nazc80fIdb:ta8Ya8PN:tgIN:ta81:vgxam:tg8Ra8RNa8Pa8X:va8YaIa8Z:va8WaxN:tg8XN:ta80axN:tg8Wa8S:tg8Ya8YNa8XaA:tg8Ya8YNMMa8N9DTmbaxaRaxaR9EEgxakaRMgmaxam9DEhma8Xa8Ua8Xa8U9EEgxaka8UMgAaxaA9DEhAa8Wa8Va8Wa8V9EEgxaka8VMg8Saxa8S9DEh8SkdnaPTmbayaRMhmaya8UMhAaya8VMh8SkasamUdbaqaAUdbava8SUdbazc;abfhza3cufg3mbxdkkdnaPTmbakJbbbZNhxaQhzinazczfaxakazydbgHcFrG:ZNMUdbazcxfaxakaHcq4cFrG:ZNMUdbazcwfaxakaHcC4cFrG:ZNMUdbazc;abfhza3cufg3mbxdkkaQcCfhzinazc98fgHaHIdbazIdbgk:vUdbazc94fgHaHIdbak:vUdbazctfgHaHIdbak:vUdbazc;abfhza3cufg3mbkkcbhsdndnarcd9imbarcufh3aEarcdtfhadnabmbaKcefg8Mararcefgz2fh8JaKazfhba8MaLfh8Ecbhscbh8Kina8Kar2h8La8Mheabh8Aa8Eh8Fa8Jh5cbhXindnaEaXa8LfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbclcbaKaqar2fgzarfRbbEazRbbcb9hVczcbazaLfgzRbbEVc;abcbazarfRbbEVhPaehza8AhHa8Fhqa5hva3hQindnaPclcbaHRbbEazRbbcb9hVczcbaqRbbEVc;abcbavRbbEVgPcetVgCTmbaCcFeSmbasaCRb;W;p:cjbfhskazcefhzaHcefhHaqcefhqavcefhvaQcufgQmbkkaearfhea8Aarfh8Aa8Farfh8Fa5arfh5aXcefgXa39hmbka8MaLfh8MabaLfhba8EaLfh8Ea8JaLfh8Ja8Kcefg8Ka39hmbxdkkJbbjZaO:vgkakJk;x8J88NNh8RawcdGh8EaDIdwhkaDIdlhxaDIdbhmcbhscbhPinaPar2h8KcbhvindnaEava8KfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbcbh8AclcbaKaqar2fgYarfRbbEaYRbbcb9hVczcbaYaLfg8JRbbEVc;abcba8JarfRbbEVh8Lindna8LclcbaYa8Ag8Mcefg8AfgzarfRbbEazRbbcb9hVczcba8Ja8AfgzRbbEVc;abcbazarfRbbEVg8LcetVgCTmbaCcFeSmbcbhqdndndnaCRb;W;n:cjbcufPdebdka8ETmeaCcC2gz8Ve;W:L:cjbcltaz8Ve;Y:L:cjbcsGVh8FaKa8Mfh5cxhzaDcjefhHinaHaQaEa8Faz4gqce4ceGavfaqcd4ceGaPfar2fgXcdtfydbcotfa5aqceGfaXar2fRbbcotfcnfBdbaHclfhHazc98fgzc989hmbkaDydjegzIdyaDyd:megHIdyMaDyd:eegqIdyaDyd1egXIdyMMg8XaqIdwaXIdwMJbbbZNgANazIdUaHIdUMaqIdUaXIdUMMg8WMg8Sa8SMazIdaaHIdaMaqIdaaXIdaMMg8YaqIdzaXIdzMJbbbZNg8SNMa8SNazId8SaHId8SMaqId8SaXId8SMMgRa8SNazId80aHId80MaqId80aXId80MMg8UMg8Sa8SMazId3aHId3MaqId3aXId3MMg8VaqIdxaXIdxMJbbbZNg8SNMa8SNazId8KaHId8KMaqId8KaXId8KMMg8Za8SNazId8WaHId8WMaqId8WaXId8WMMg80Mg8Sa8SMazIdKaHIdKMaqIdKaXIdKMMgyaANMaANazId88aHId88MaqId88aXId88MMg8PMMM:lgIa8RazIdCaHIdCMaqIdCaXIdCMMN9Ea8XazIdwaHIdwMJbbbZNgANa8WMg8Sa8SMa8YazIdzaHIdzMJbbbZNg8SNMa8SNaRa8SNa8UMg8Sa8SMa8VazIdxaHIdxMJbbbZNg8SNMa8SNa8Za8SNa80Mg8Sa8SMayaANMaANa8PMMM:laIJ;d;1UZN9DGhqxekaKa8Mfh8FcbhzcrhHindnaCaz4ceGTmba8FazceGfazce4ceGavfazcd4aPfar2fgqar2fRbbgXcFeSmbaQaEaqcdtfydbcotfaXcotfc9efRbbaH4ceGTmbcbhqxdkaHcufhHcehqazcefgzcw9hmbkkaCcC2aqcq2fgH8Ve;W:L:cjbgzTmbaHc;Y:L:cjbfhqaKa8MfhCabasc8K2fhHindnasae9pmbaHaQaEazcD4ceGavfazcq4ceGaPfar2fgXcdtfydbcotfaCazcw4ceGfaXar2fRbbcotfgXc9ifIdbamMUdbaHclfaXc9mfIdbaxMUdbaHcwfaXc9qfIdbakMUdbaHcxfamaQaEazcv4ceGavfazco4ceGaPfar2fgXcdtfydbcotfaCazcl4ceGfaXar2fRbbcotfgXc9ifIdbMUdbaHczfaxaXc9mfIdbMUdbaHcCfakaXc9qfIdbMUdbaHcKfamaQaEazce4ceGavfazcd4ceGaPfar2fgXcdtfydbcotfaCazceGfaXar2fRbbcotfgzc9ifIdbMUdbaHc3faxazc9mfIdbMUdbaHcafakazc9qfIdbMUdbkaHc8KfhHascefhsaq8Vebhzaqcdfhqazmbkka8Aa39hmbkkavcefgva39hmbkaPcefgPa39hmbkaDyd2gYTmekaYcdtaDcxffc98fhzinazydbcbyd;C:L:cjbH:bjjjbbazc98fhzaYcufgYmbkkaDcjif8Kjjjjbask;Kxmiue99due99euz99eui99eud99dud99oudnalTmbaocd4hkaqcdGhxarc99fhqarcethmawawMhPcbhsindndnawavaiascdtfgoclfydbak2cdtfgzIdwgHavaoydbak2cdtfgOIdwgA:tgCaCNazIdbgXaOIdbgQ:tgLaLNazIdlgKaOIdlgY:tg8Aa8ANMMgEavaocwfydbak2cdtfgoIdwg3aA:tg5a5NaoIdbg8EaQ:tg8Fa8FNaoIdlgaaY:tghahNMMggaEag9EEgEa3aH:tgHaHNa8EaX:tgHaHNaaaK:tgHaHNMMgHaEaH9EE:rNgHaHMgH:lJbbb9p9DTmbaH:Ohoxekcjjjj94hokdnaLahNa8Aa8FN:tgHaHNa8Aa5NaCahN:tgXaXNaCa8FNaLa5N:tgKaKNMMg3Jbbbb9BmbJbbjZhEdnaoceaoce9kEgoamaoam9iEg8Jcd9imbJbbjZa8J:Z:vhEkarcb9imbaAaDIdw:th8KaYaDIdl:th8LaQaDIdb:th8Ma8Jcba8Jcb9kEh8NdnadTmbaHJbbjZa3:rgA:vgQNg3aAa8Jcefa8Jcdf2:Y:vgANh8EaKaQNgKaANhyaXaQNgXaXaANNh8PcbhIina8Jcba8Jcb9kEcefh8RaEaI:ZNgQaCNa8KMhgaQa8ANa8LMh8SaQaLNa8MMhRcbhzindndnaPaEaz:ZNgQahNa8SMgYNgH:lJbbb9p9DTmbaH:OhOxekcjjjj94hOkaOce91goaqaoaq6Eh8UdndnaPaQa5NagMgHNga:lJbbb9p9DTmbaa:Oh8Vxekcjjjj94h8Vka8Ua8Vce91goaqaoaq6Eg8Wcefar2fcefgoar2h8XdndnaPaQa8FNaRMgQNga:lJbbb9p9DTmbaa:Oh8Yxekcjjjj94h8Ykadaeaocdtfydbcotfaba8Yce91goaqaoaq6Eg8Zfa8XfcefRbbcotfgocnfa8Ucqta8ZcCtVa8WVBdbaoc9efg8Ua8URbbcea8YceGaOcetcdGVa8VcdtclGVtV86bbaoc9ifgOaQaANaOIdbMUdbaoc9mfgOaYaANaOIdbMUdbaoc9qfgOaHaANaOIdbMUdbaoc9ufgOaAaOIdbMUdbdnaxTmbaoc9yfgOa8PaOIdbMUdbaoc9CfgOaKayNaOIdbMUdbaoc9GfgOa3a8ENaOIdbMUdbaoc9KfgOaXayNaOIdbMUdbaoc9OfgOaXa8ENaOIdbMUdbaoc2fgOaKa8ENaOIdbMUdbaoc9WfgOaXaAa3aHNaXaQNaKaYNMMgY:mNgQNaOIdbMUdbaoctfgOaKaQNaOIdbMUdbaoc94fgOa3aQNaOIdbMUdbaoc98fgoaoIdbaYaQN:tUdbka8Razcefgz9hmbka8Jcufh8JaIa8NShoaIcefhIaoTmbxdkkcbh8Vina8Jcba8Jcb9kEcefh8UaEa8V:ZNgAaCNa8KMhYaAa8ANa8LMhHaAaLNa8MMhXcbhoindndnaPaEao:ZNgAahNaHMNgQ:lJbbb9p9DTmbaQ:Ohzxekcjjjj94hzkazce91gzaqazaq6EhzdndnaPaAa5NaYMNgQ:lJbbb9p9DTmbaQ:OhOxekcjjjj94hOkazaOce91gOaqaOaq6Ecefar2fcefar2hzdndnaPaAa8FNaXMNgA:lJbbb9p9DTmbaA:OhOxekcjjjj94hOkabaOce91gOaqaOaq6Efazfcefce86bba8Uaocefgo9hmbka8Jcufh8Ja8Va8NShoa8Vcefh8VaoTmbkkascifgsal6mbkkk:Nvezu8Jjjjjbcjd9Rgb8Kjjjjbcbheabcbcjdz:xjjjbhdc:W:H:cjbhbinabRbbgicC2glabcqf8Veb87e;4:L:cjbalabcdfgv8Peb83e;W:L:cjbaiabcefRbb86b;W;n:cjbadaifce86bbalavabcxfceaetc:F:d;avGEgi8Peb83e;6:L:cjbalai8Vew87e:c:M:cjbabcQfhbaecefgecK9hmbkcbhoinc;Y:L:cjbhrcbhvindnadavfgwRbbce9hmbavcC2c;W:L:cjbfhDcbhbcehqavc;W;n:cjbfhkinabcitc:G:H:cjbfhlcbhbcbheinaeavab4ceGalabfRbbtVheabcefgbcw9hmbkdnadaecFeGgxfgmRbbmbaxcC2c;W:L:cjbfhPcbhbcehsindnaDabcq2gif8VebgbTmbaraifheaPaifhiinaialabcl4csGfRbbcltalabcw4csGfRbbcwtValabcsGfRbbV87ebaicdfhiae8VebhbaecdfheabmbkkcehbasceGhecbhsaembkamce86bbaxakRbb86b;W;n:cjbkcehbaqceGhlcbhqalmbkawcd86bbkarcCfhravcefgvcjd9hmbkaocefgoci9hmbkcbhic;W:L:cjbhvincuhlavhbinalcefhlab8Vebheabcdfhbaembkaial86b;W;p:cjbavcCfhvaicefgicjd9hmbkadcjdf8Kjjjjbk9DeeuabcFeaicdtz:xjjjbhlcbhbdnadTmbindnalaeydbcdtfgiydbcu9hmbaiabBdbabcefhbkaeclfheadcufgdmbkkabk;Bidqui998Jjjjjbc;Wb9Rgl8Kjjjjbalcxfcbc;Kbz:xjjjb8Aadcd4adfhvcehoinaogrcethoarav6mbkalcuarcdtgoarcFFFFi0Ecbyd;y:L:cjbHjjjjbbgvBdxavcFeaoz:xjjjbhwdnadTmbaicd4hDarcufhqcbhkindndnawcbaeakaD2cdtfgrydlgiaicjjjj94SEgocH4ao7c:F:b:DD2cbarydbgxaxcjjjj94SEgocH4ao7c;D;O:B8J27cbarydwgmamcjjjj94SEgrcH4ar7c:3F;N8N27aqGgvcdtfgrydbgocuSmbam::hPai::hsax::hzcehiinaihrdnaeaoaD2cdtfgiIdbaz9CmbaiIdlas9CmbaiIdwaP9BmikarcefhiawavarfaqGgvcdtfgrydbgocu9hmbkkarakBdbakhokabakcdtfaoBdbakcefgkad9hmbkkalydxcbyd;C:L:cjbH:bjjjbbalc;Wbf8Kjjjjbk9teiucbcbyd;G:L:cjbgeabcifc98GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd;G:L:cjbgeabcrfc94GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd;G:L:cjbge9Rcifc98GaefgbBd;G:L:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akk6eiucbhidnadTmbdninabRbbglaeRbbgv9hmeaecefheabcefhbadcufgdmbxdkkalav9Rhikaikk;0vdbcj:Gdk;yvFFuuFFuuFFuuFFuFFFuFFFuFbbbbbbbbebbbdbbbbbbbebbbebbbdbbbbbbbbbbbeeeeeebebbeebbebbebbbeeebbbbebbbbbbbbbbbbbbbbbbbeeeeeeebebbbeeebbeebbbbbebbbbbebebbbbbbbbbbbbbbbdiorbelvlbodveribbbbbbbbbbbbbbbbbbbbbbebbbbbbbbbbbbbbbbbbbbbibbbbbbbbbbbbbbbbbbbbbobbbbbbbbbbbbbbbbbbbbbrbaebbbbbbbbbbbbbbbbbbsd8We8YbbbbbbbhiaebbbbbbQe8Ke9cebbbbbbbbbbbbbbbbLb8KebbbbbbbbbbbbbbbbbbKbbbbbbbbbbbbbbbbbbbbbYeJbilbbbbbbbbbbbbbbbbEe80e8WlbbbbbbzlAbbbbbbb5eJdnibbbbbbai8Kbbbbbbb8Ee9ce8Ylcibbbb8Yebbbbbbbb8FdOlAdbbbbbb80e8Ylbbbbbb88eTi8KiJv8Jlbbbbbbbbbbbb89e9td8Kv9qibbbbndlvaibbbbZd8Li8KvbbbbbbJdTibbbbbb9Pe81b9GvoiBvbbbbbbbbbbbb9Re9JbvoWibbbbvibbbbbbbb9VeWi9Gvbbbbbb8WvBbbbbbbb9:b9ceBvbbbbbbbbbbbbbbbbubWibbbbbbbbbbbbbbbbbb;Wd9hvSrbbbbbbWl9NvbbbbbbFbbbbbbbbbbbbbbbbbbbbbFFuuFFuuFFuuFFuFFFuFFFuFbc;y:Ldkxebbbdbbb;W:Obb",t=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var e,n=WebAssembly.instantiate(a(i),{}).then(function(p){e=p.instance,e.exports.__wasm_call_ctors()});function a(p){for(var y=new Uint8Array(p.length),S=0;S<p.length;++S){var g=p.charCodeAt(S);y[S]=g>96?g-97:g>64?g-39:g+4}for(var M=0,S=0;S<p.length;++S)y[M++]=y[S]<60?t[y[S]]:(y[S]-60)*64+y[++S];return y.buffer.slice(0,M)}function s(p){if(!p)throw new Error("Assertion failed")}function r(p){return new Uint8Array(p.buffer,p.byteOffset,p.byteLength)}function o(p,y,S,g){var M=e.exports.sbrk,E=M(S*4),A=M(S*g*4),I=new Uint8Array(e.exports.memory.buffer);I.set(r(y),A),p(E,A,S,g*4),I=new Uint8Array(e.exports.memory.buffer);var C=new Uint32Array(S);return new Uint8Array(C.buffer).set(I.subarray(E,E+S*4)),M(E-M(0)),C}function c(p,y,S){var g=e.exports.sbrk,M=g(y.length*4),E=g(S*4),A=new Uint8Array(e.exports.memory.buffer),I=r(y);A.set(I,M);var C=p(E,M,y.length,S);A=new Uint8Array(e.exports.memory.buffer);var P=new Uint32Array(S);new Uint8Array(P.buffer).set(A.subarray(E,E+S*4)),g(M-g(0));for(var N=0;N<y.length;++N)y[N]=P[y[N]];return[P,C]}function l(p){for(var y=0,S=0;S<p.length;++S){var g=p[S];y=y<g?g:y}return y}function h(p,y,S,g,M,E,A,I,C){var P=e.exports.sbrk,N=P(4),U=P(S*4),z=P(M*E),F=P(S*4),K=new Uint8Array(e.exports.memory.buffer);K.set(r(g),z),K.set(r(y),F);var H=p(U,F,S,z,M,E,A,I,C,N);K=new Uint8Array(e.exports.memory.buffer);var J=new Uint32Array(H);r(J).set(K.subarray(U,U+H*4));var tt=new Float32Array(1);return r(tt).set(K.subarray(N,N+4)),P(N-P(0)),[J,tt[0]]}function u(p,y,S,g,M,E,A,I,C,P,N,U,z){var F=e.exports.sbrk,K=F(4),H=F(S*4),J=F(M*E),tt=F(M*I),ft=F(C.length*4),Ct=F(S*4),q=P?F(M):0,st=new Uint8Array(e.exports.memory.buffer);st.set(r(g),J),st.set(r(A),tt),st.set(r(C),ft),st.set(r(y),Ct),P&&st.set(r(P),q);var xt=p(H,Ct,S,J,M,E,tt,I,ft,C.length,q,N,U,z,K);st=new Uint8Array(e.exports.memory.buffer);var It=new Uint32Array(xt);r(It).set(st.subarray(H,H+xt*4));var mt=new Float32Array(1);return r(mt).set(st.subarray(K,K+4)),F(K-F(0)),[It,mt[0]]}function d(p,y,S,g,M,E,A,I,C,P,N,U,z){var F=e.exports.sbrk,K=F(4),H=F(M*E),J=F(M*I),tt=F(C.length*4),ft=F(S*4),Ct=P?F(M):0,q=new Uint8Array(e.exports.memory.buffer);q.set(r(g),H),q.set(r(A),J),q.set(r(C),tt),q.set(r(y),ft),P&&q.set(r(P),Ct);var st=p(ft,S,H,M,E,J,I,tt,C.length,Ct,N,U,z,K);q=new Uint8Array(e.exports.memory.buffer),r(y).set(q.subarray(ft,ft+st*4)),r(g).set(q.subarray(H,H+M*E)),r(A).set(q.subarray(J,J+M*I));var xt=new Float32Array(1);return r(xt).set(q.subarray(K,K+4)),F(K-F(0)),[st,xt[0]]}function f(p,y,S,g){var M=e.exports.sbrk,E=M(S*g),A=new Uint8Array(e.exports.memory.buffer);A.set(r(y),E);var I=p(E,S,g);return M(E-M(0)),I}function b(p,y,S,g,M,E,A,I){var C=e.exports.sbrk,P=C(I*4),N=C(S*g),U=M?C(S*E):0,z=new Uint8Array(e.exports.memory.buffer);z.set(r(y),N),M&&z.set(r(M),U);var F=p(P,N,S,g,U,E,A,I);z=new Uint8Array(e.exports.memory.buffer);var K=new Uint32Array(F);return r(K).set(z.subarray(P,P+F*4)),C(P-C(0)),K}function _(p,y,S,g,M,E,A,I,C){var P=e.exports.sbrk,N=P(4),U=P(S*4),z=P(M*E),F=P(S*4),K=A?P(M):0,H=new Uint8Array(e.exports.memory.buffer);H.set(r(g),z),H.set(r(y),F),A&&H.set(r(A),K);var J=p(U,F,S,z,M,E,K,I,C,N);H=new Uint8Array(e.exports.memory.buffer);var tt=new Uint32Array(J);r(tt).set(H.subarray(U,U+J*4));var ft=new Float32Array(1);return r(ft).set(H.subarray(N,N+4)),P(N-P(0)),[tt,ft[0]]}function m(p,y,S,g,M,E,A){var I=e.exports.sbrk,C=I(S*4),P=I(M*E),N=I(S*4),U=new Uint8Array(e.exports.memory.buffer);U.set(r(g),P),U.set(r(y),N);var z=p(C,N,S,P,M,E,A);U=new Uint8Array(e.exports.memory.buffer);var F=new Uint32Array(z);return r(F).set(U.subarray(C,C+z*4)),I(C-I(0)),F}function x(p,y,S,g,M,E){var A=e.exports.sbrk,I=A(S.byteLength),C=A(y.byteLength),P=new Uint8Array(e.exports.memory.buffer);P.set(r(S),I),P.set(r(y),C);var N=S.byteLength/g,U=p(0,0,C,y.length,I,N,g,M,E),z=A(U*9*4),F=p(z,U,C,y.length,I,N,g,M,E);s(F<=U),P=new Uint8Array(e.exports.memory.buffer);var K=new Float32Array(F*9);return r(K).set(P.subarray(z,z+K.byteLength)),A(I-A(0)),K}var v={LockBorder:1,Sparse:2,ErrorAbsolute:4,Prune:8,Regularize:16,Permissive:32,RegularizeLight:64,PreserveFolds:128,ErrorClamped:256,_InternalDebug:1<<30},w={Shell:1,Solve:2,Thicken:0,_InternalDebug:1<<30};return{ready:n,supported:!0,compactMesh:function(p){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0);var y=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),S=c(e.exports.meshopt_optimizeVertexFetchRemap,y,l(p)+1);if(p!==y)for(var g=0;g<y.length;++g)p[g]=y[g];return S},generatePositionRemap:function(p,y){return s(p instanceof Float32Array),s(p.length%y==0),s(y>=3),o(e.exports.meshopt_generatePositionRemap,p,p.length/y,y)},simplify:function(p,y,S,g,M,E){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(y instanceof Float32Array),s(y.length%S==0),s(S>=3),s(g>=0&&g<=p.length),s(g%3==0),s(M>=0);for(var A=0,I=0;I<(E?E.length:0);++I)s(E[I]in v),A|=v[E[I]];var C=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),P=h(e.exports.meshopt_simplify,C,p.length,y,y.length/S,S*4,g,M,A);return P[0]=p instanceof Uint32Array?P[0]:new p.constructor(P[0]),P},simplifyWithAttributes:function(p,y,S,g,M,E,A,I,C,P){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(y instanceof Float32Array),s(y.length%S==0),s(S>=3),s(g instanceof Float32Array),s(g.length==M*(y.length/S)),s(M>=0),s(A==null||A instanceof Uint8Array),s(A==null||A.length==y.length/S),s(I>=0&&I<=p.length),s(I%3==0),s(C>=0),s(Array.isArray(E)),s(M>=E.length),s(E.length<=32);for(var N=0;N<E.length;++N)s(E[N]>=0);for(var U=0,N=0;N<(P?P.length:0);++N)s(P[N]in v),U|=v[P[N]];var z=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),F=u(e.exports.meshopt_simplifyWithAttributes,z,p.length,y,y.length/S,S*4,g,M*4,new Float32Array(E),A,I,C,U);return F[0]=p instanceof Uint32Array?F[0]:new p.constructor(F[0]),F},simplifyWithUpdate:function(p,y,S,g,M,E,A,I,C,P){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(y instanceof Float32Array),s(y.length%S==0),s(S>=3),s(g instanceof Float32Array),s(g.length==M*(y.length/S)),s(M>=0),s(A==null||A instanceof Uint8Array),s(A==null||A.length==y.length/S),s(I>=0&&I<=p.length),s(I%3==0),s(C>=0),s(Array.isArray(E)),s(M>=E.length),s(E.length<=32);for(var N=0;N<E.length;++N)s(E[N]>=0);for(var U=0,N=0;N<(P?P.length:0);++N)s(P[N]in v),U|=v[P[N]];var z=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),F=d(e.exports.meshopt_simplifyWithUpdate,z,p.length,y,y.length/S,S*4,g,M*4,new Float32Array(E),A,I,C,U);if(p!==z)for(var N=0;N<F[0];++N)p[N]=z[N];return F},getScale:function(p,y){return s(p instanceof Float32Array),s(p.length%y==0),s(y>=3),f(e.exports.meshopt_simplifyScale,p,p.length/y,y*4)},simplifyPoints:function(p,y,S,g,M,E){return s(p instanceof Float32Array),s(p.length%y==0),s(y>=3),s(S>=0&&S<=p.length/y),g?(s(g instanceof Float32Array),s(g.length%M==0),s(M>=3),s(p.length/y==g.length/M),b(e.exports.meshopt_simplifyPoints,p,p.length/y,y*4,g,M*4,E||0,S)):b(e.exports.meshopt_simplifyPoints,p,p.length/y,y*4,void 0,0,0,S)},simplifySloppy:function(p,y,S,g,M,E){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(y instanceof Float32Array),s(y.length%S==0),s(S>=3),s(g==null||g instanceof Uint8Array),s(g==null||g.length==y.length/S),s(M>=0&&M<=p.length),s(M%3==0),s(E>=0);var A=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),I=_(e.exports.meshopt_simplifySloppy,A,p.length,y,y.length/S,S*4,g,M,E);return I[0]=p instanceof Uint32Array?I[0]:new p.constructor(I[0]),I},simplifyPrune:function(p,y,S,g){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(y instanceof Float32Array),s(y.length%S==0),s(S>=3),s(g>=0);var M=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),E=m(e.exports.meshopt_simplifyPrune,M,p.length,y,y.length/S,S*4,g);return E=p instanceof Uint32Array?E:new p.constructor(E),E},remesh:function(p,y,S,g,M){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(y instanceof Float32Array),s(y.length%S==0),s(S>=3),s(g>=4&&g<=256);for(var E=0,A=0;A<(M?M.length:0);++A)s(M[A]in w),E|=w[M[A]];var I=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p);return x(e.exports.meshopt_remesh,I,y,S*4,g,E)}}})();var AM=6e4,Bd=3e4;function Nm(i,t,e){let n=new Float32Array(3*e);for(let a=0;a<t.length;a++){let s=t[a];s!==4294967295&&(n[3*s]=i[3*a],n[3*s+1]=i[3*a+1],n[3*s+2]=i[3*a+2])}return n}function EM(i,t){let e=new Uint32Array(i.buffer,i.byteOffset,i.length),[n]=Ms.simplify(e,t,3,3*Bd,1);return n.length>6*Bd&&([n]=Ms.simplifySloppy(e,t,3,null,3*Bd,1)),n.length?n:null}function Pm({stage:i,surface:t,outlines:e,root:n}){let a=i.scene,s=null,r=!1,o=!1;function c(d,f){if(d.length/3<=AM)return;let b=t.geometry();Ms.ready.then(()=>{if(t.geometry()!==b||!Ms.supported)return;let _=EM(d,f);if(!_)return;let[m,x]=Ms.compactMesh(_),v=new Zn;v.setAttribute("position",new ze(Nm(b.getAttribute("position").array,m,x),3)),v.setIndex(new ze(_,1)),v.boundingSphere=b.boundingSphere,s=new cn(v,t.material),s.userData={remap:m,unique:x,normal:null},s.visible=!1,a.add(s),n.dataset.coarseFaces=String(_.length/3)})}function l(d){let f=t.geometry();if(!f||r===d||(r=d,e.show(d),n.dataset.turning=String(d),i.requestRender(),!s))return;let b=f.getAttribute("normal"),_=s.userData;b&&_.normal!==b&&(_.normal=b,s.geometry.setAttribute("normal",new ze(Nm(b.array,_.remap,_.unique),3))),s.visible=d,t.mesh().visible=!d}let h=ys(i.controls,{start:()=>{o=!0},change:()=>{o&&l(!0)},end:()=>{o=!1,l(!1)}});function u(){r=!1,n.dataset.turning="false",s&&(a.remove(s),s.geometry.dispose(),s=null)}return{draw:c,clear:u,dispose(){u(),h()}}}var Lm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),TM=globalThis[Lm]||(globalThis[Lm]=(bs(),Ra(gs))),{LineMaterial:qr}=TM;var Dm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),IM=globalThis[Dm]||(globalThis[Dm]=(bs(),Ra(gs))),{LineSegments2:kd}=IM;var Um=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),RM=globalThis[Um]||(globalThis[Um]=(bs(),Ra(gs))),{LineSegmentsGeometry:zd}=RM;var Vd=2e3,CM=6e3,NM=3e4,Om=["flipped","boundary","non_manifold"];function Fm(i,t,e){let n=new Float32Array(6*e.length);for(let a=0;a<e.length;a++){let s=e[a],r=t[s],o=t[s%3===2?s-2:s+1];for(let c=0;c<3;c++)n[6*a+c]=i[3*r+c],n[6*a+3+c]=i[3*o+c]}return n}function Bm(i){let t=new Int32Array(3*i.length);for(let e=0;e<i.length;e++)for(let n=0;n<3;n++)t[3*e+n]=3*i[e]+n;return t}function PM(i,t,e){let n=new Map;for(let a=0;a<t.length;a++)for(let s=0;s<3;s++){let r=3*t[a]+s,o=i[r],c=i[3*t[a]+(s+1)%3],l=o<c?o*e+c:c*e+o;n.set(l,n.has(l)?-1:r)}return Int32Array.from([...n.values()].filter(a=>a>=0)).sort()}function km(i,t){let e=i.flipped||new Int32Array(0);return{flipped:e.length>Vd?PM(i.faces,e,t):Bm(e),boundary:i.boundary||new Int32Array(0),non_manifold:i.non_manifold||new Int32Array(0)}}function zm(i){let t={flipped:new qr({linewidth:2.5}),boundary:new qr({linewidth:4}),non_manifold:new qr({linewidth:4})},e=Object.fromEntries(Om.map(d=>[d,new Vr])),n=new qr({linewidth:4}),a={},s={},r=null;function o(d,f,b){for(let[_,m]of Object.entries(b)){if(!m.length)continue;let x=Fm(d,f,m),v=new Zn;v.setAttribute("position",new ze(x,3));let w=new pl(v,e[_]);if(w.renderOrder=1,w.userData.sides=m.length,s[_]=w,i.add(w),m.length>CM)continue;let p=new zd;p.setPositions(x);let y=new kd(p,t[_]);y.renderOrder=1,a[_]=y,i.add(y)}}function c(d){for(let[f,b]of Object.entries(s))a[f]&&(a[f].visible=!d),b.visible=d?b.userData.sides<=NM:!a[f]}function l(d,f,b){h();let _=new zd;_.setPositions(Fm(d,f,Bm([b]))),r=new kd(_,n),r.renderOrder=3,i.add(r)}function h(){r&&(i.remove(r),r.geometry.dispose(),r=null)}function u(){for(let d of[...Object.values(a),...Object.values(s)])i.remove(d),d.geometry.dispose();a={},s={},h()}return{draw:o,show:c,showPicked:l,clearPicked:h,setColors(d,f){for(let b of Om)t[b].color=new kn(d(b)),e[b].color=new kn(d(b));n.color=new kn(f)},setResolution(d,f){for(let b of[...Object.values(t),n])b.resolution.set(d,f)},clear:u,dispose(){u();for(let d of[...Object.values(t),...Object.values(e),n])d.dispose()}}}var LM=[["front","front of a face (its normal points out of this side)","face"],["back","back of a face","face"],["flipped","outline: a face to flip","line"],["boundary","thick: an edge with one face (the rim of a hole)","line"],["non_manifold","thick: an edge with three faces or more","line"],["face_arrows","arrow from a face's centre: its unit normal","arrow"],["vertex_arrows","arrow from a vertex: its vertex normal","arrow"]];function Vm(i,{counts:t,shown:e,colorOf:n}){i.textContent="";for(let[a,s,r]of LM){if(r==="line"&&!t[a]||r==="arrow"&&!(t[a]&&e(a)))continue;let o=Xt("li","tnm-key"),c=Xt("span","tnm-swatch tnm-swatch-"+(r==="arrow"?"line":r));c.style.setProperty("--tnm-swatch",n(a)),c.setAttribute("aria-hidden","true");let l=a==="flipped"&&t.flipped>Vd,h=l?` (${t[a]} faces)`:r==="line"?` (${t[a]})`:r==="arrow"?` (${t[a]} drawn)`:"";o.append(c,i.ownerDocument.createTextNode((l?"outline: the rim of each patch of faces to flip":s)+h)),i.appendChild(o)}}function Hm(i,t){if(i.textContent="",i.hidden=!(t&&t.rows&&t.rows.length),i.hidden)return;i.appendChild(Xt("p","tnm-pick-title",t.title||""));let e=Xt("dl","tnm-pick-rows");for(let[n,a]of t.rows)e.append(Xt("dt","",n),Xt("dd","",a));i.appendChild(e)}var Ss=Math.pow(2,-24),Yr=Symbol("SKIP_GENERATION"),Al={strategy:0,maxDepth:40,targetLeafSize:10,useSharedArrayBuffer:!1,setBoundingBox:!0,onProgress:null,indirect:!1,verbose:!0,range:null,[Yr]:!1};function _e(i,t,e){return e.min.x=t[i],e.min.y=t[i+1],e.min.z=t[i+2],e.max.x=t[i+3],e.max.y=t[i+4],e.max.z=t[i+5],e}function Jr(i){let t=-1,e=-1/0;for(let n=0;n<3;n++){let a=i[n+3]-i[n];a>e&&(e=a,t=n)}return t}function Hd(i,t,e){for(let n=0;n<3;n++){let a=t[i+2*n],s=t[i+2*n+1],r=a-s,o=a+s;r<e[n]&&(e[n]=r),o>e[n+3]&&(e[n+3]=o)}}function El(i){let t=i[3]-i[0],e=i[4]-i[1],n=i[5]-i[2];return 2*(t*e+e*n+n*t)}function ee(i,t){return t[i+15]===65535}function fe(i,t){return t[i+6]}function be(i,t){return t[i+14]}function le(i){return i+8}function he(i,t){let e=t[i+6];return i+e*8}function ws(i,t){return t[i+7]}function Tl(i,t,e,n,a){let s=1/0,r=1/0,o=1/0,c=-1/0,l=-1/0,h=-1/0,u=1/0,d=1/0,f=1/0,b=-1/0,_=-1/0,m=-1/0,x=i.offset||0;for(let v=(t-x)*6,w=(t+e-x)*6;v<w;v+=6){let p=i[v+0],y=i[v+1],S=p-y,g=p+y;S<s&&(s=S),g>c&&(c=g),p<u&&(u=p),p>b&&(b=p);let M=i[v+2],E=i[v+3],A=M-E,I=M+E;A<r&&(r=A),I>l&&(l=I),M<d&&(d=M),M>_&&(_=M);let C=i[v+4],P=i[v+5],N=C-P,U=C+P;N<o&&(o=N),U>h&&(h=U),C<f&&(f=C),C>m&&(m=C)}n[0]=s,n[1]=r,n[2]=o,n[3]=c,n[4]=l,n[5]=h,a[0]=u,a[1]=d,a[2]=f,a[3]=b,a[4]=_,a[5]=m}var gi=8,Wd=8,Gd=new Int32Array(gi),mi=new Float32Array(gi*6),As=new Float32Array(gi*6),$n=new Float32Array(6),Il=new Float32Array(6),ta=new Int32Array(Wd),Wm=new Float32Array(Wd*6);function OM(i,t,e,n){for(let a=0;a<3;a++){let s=t[i+2*a],r=t[i+2*a+1],o=s-r,c=s+r;o<e[n+a]&&(e[n+a]=o),c>e[n+a+3]&&(e[n+a+3]=c)}}function jm(i,t){let e=i[t+3]-i[t],n=i[t+4]-i[t+1],a=i[t+5]-i[t+2];return 2*(e*n+n*a+a*e)}function Xm(i,t,e,n,a,s){let r=-1,o=0;if(s===0)r=Jr(t),r!==-1&&(o=(t[r]+t[r+3])/2);else if(s===1)r=Jr(i),r!==-1&&(o=FM(e,n,a,r));else if(s===2){let c=El(i),l=1.25*a,h=e.offset||0,u=(n-h)*6,d=(n+a-h)*6;for(let f=0;f<3;f++){let b=t[f],x=(t[f+3]-b)/gi;if(a<Wd){for(let v=0;v<a;v++){let w=u+v*6,p=e[w+2*f],y=v;for(;y>0&&e[ta[y-1]+2*f]>p;)ta[y]=ta[y-1],y--;ta[y]=w}for(let v=0;v<3;v++)$n[v]=1/0,$n[v+3]=-1/0,Il[v]=1/0,Il[v+3]=-1/0;for(let v=a-1;v>=0;v--)Hd(ta[v],e,Il),Wm.set(Il,v*6);for(let v=0;v<a-1;v++){Hd(ta[v],e,$n);let w=e[ta[v+1]+2*f];if(e[ta[v]+2*f]===w)continue;let p=v+1,y=a-p,S=El($n)/c,g=jm(Wm,p*6)/c,M=1+1.25*(S*p+g*y);M<l&&(r=f,l=M,o=w)}}else{for(let p=0;p<gi;p++){Gd[p]=0;for(let y=0;y<3;y++)mi[p*6+y]=1/0,mi[p*6+y+3]=-1/0}for(let p=u;p<d;p+=6){let g=~~((e[p+2*f]-b)/x);g>=gi&&(g=gi-1),Gd[g]++,OM(p,e,mi,g*6)}let v=(gi-1)*6;for(let p=0;p<6;p++)As[v+p]=mi[v+p];for(let p=gi-2;p>=0;p--){let y=p*6,S=y+6;for(let g=0;g<3;g++)As[y+g]=Math.min(mi[y+g],As[S+g]),As[y+g+3]=Math.max(mi[y+g+3],As[S+g+3])}let w=0;for(let p=0;p<gi-1;p++){let y=p*6,S=Gd[p];if(S!==0)for(let I=0;I<3;I++)w===0?($n[I]=mi[y+I],$n[I+3]=mi[y+I+3]):($n[I]=Math.min($n[I],mi[y+I]),$n[I+3]=Math.max($n[I+3],mi[y+I+3]));w+=S;let g=0,M=0;w!==0&&(g=El($n)/c);let E=a-w;E!==0&&(M=jm(As,y+6)/c);let A=1+1.25*(g*w+M*E);A<l&&(r=f,l=A,o=b+x+p*x)}}}}else console.warn(`BVH: Invalid build strategy value ${s} used.`);return{axis:r,pos:o}}function FM(i,t,e,n){let a=0,s=i.offset;for(let r=t,o=t+e;r<o;r++)a+=i[(r-s)*6+n*2];return a/e}function qm(i,t,e,n,a,s){let r=n,o=n+a-1,c=s.pos,l=s.axis*2,h=e.offset||0;for(;;){for(;r<=o&&e[(r-h)*6+l]<c;)r++;for(;r<=o&&e[(o-h)*6+l]>=c;)o--;if(r<o){for(let u=0;u<t;u++){let d=i[r*t+u];i[r*t+u]=i[o*t+u],i[o*t+u]=d}for(let u=0;u<6;u++){let d=r-h,f=o-h,b=e[d*6+u];e[d*6+u]=e[f*6+u],e[f*6+u]=b}r++,o--}else return r}}var BM=Math.pow(2,32),Es=new Float32Array(6),Rl=new Float32Array(6);function kM(i,t,e,n,a,s){let{maxDepth:r,verbose:o,targetLeafSize:c,_strictLeafSize:l=1/0,strategy:h,onProgress:u,useSharedArrayBuffer:d=!1}=a,f=i.primitiveBuffer,b=i.primitiveBufferStride,_=d?SharedArrayBuffer:ArrayBuffer,m=new _(32*Math.max(1,2*Math.ceil(n)-1)),x=new Float32Array(m),v=new Uint32Array(m),w=new Uint16Array(m),p=0,y=!1;return Tl(t,e,n,Es,Rl),M(e,n,0),m.slice(0,p*32);function S(E){u&&u((E-s.offset)/s.count)}function g(E,A,I){let C=E*2;v[E+6]=A,w[C+14]=I,w[C+15]=65535,S(A+I)}function M(E,A,I){let C=p++,P=C*8;x.set(Es,P),!y&&I>=r&&(y=!0,o&&console.warn(`BVH: Max depth of ${r} reached when generating BVH. Consider increasing maxDepth.`));let N=A>l;if(A<=c&&!N||I>=r){g(P,E,A);return}let U=Xm(Es,Rl,t,E,A,h),z=U.axis===-1?-1:qm(f,b,t,E,A,U);if(U.axis===-1||z===E||z===E+A){if(!N){g(P,E,A);return}U.axis=Math.max(0,Jr(Es)),z=E+Math.max(1,Math.floor(A/2))}v[P+7]=U.axis;let F=z-E;Tl(t,E,F,Es,Rl),M(E,F,I+1);let K=p-C;if(K>BM)throw new Error("MeshBVH: Cannot store relative child node offset greater than 32 bits.");v[P+6]=K;let H=A-F;Tl(t,z,H,Es,Rl),M(z,H,I+1)}}function Ym(i,t){let e=i.getRootRanges(t.range),n=e[0],a=e[e.length-1],s={offset:n.offset,count:a.offset+a.count-n.offset},r=new Float32Array(6*s.count);r.offset=s.offset,i.computePrimitiveBounds(s.offset,s.count,r),i._roots=e.map(o=>kM(i,r,o.offset,o.count,t,s))}var ea=class{constructor(t){this._getNewPrimitive=t,this._primitives=[]}getPrimitive(){let t=this._primitives;return t.length===0?this._getNewPrimitive():t.pop()}releasePrimitive(t){this._primitives.push(t)}};var jd=class{constructor(){this.float32Array=null,this.uint16Array=null,this.uint32Array=null;let t=[],e=null;this.setBuffer=n=>{e&&t.push(e),e=n,this.float32Array=new Float32Array(n),this.uint16Array=new Uint16Array(n),this.uint32Array=new Uint32Array(n)},this.clearBuffer=()=>{e=null,this.float32Array=null,this.uint16Array=null,this.uint32Array=null,t.length!==0&&this.setBuffer(t.pop())}}},Kt=new jd;var na,Is,Ts=[],Cl=new ea(()=>new on);function Jm(i,t,e,n,a,s){na=Cl.getPrimitive(),Is=Cl.getPrimitive(),Ts.push(na,Is),Kt.setBuffer(i._roots[t]);let r=Xd(0,i.geometry,e,n,a,s);Kt.clearBuffer(),Cl.releasePrimitive(na),Cl.releasePrimitive(Is),Ts.pop(),Ts.pop();let o=Ts.length;return o>0&&(Is=Ts[o-1],na=Ts[o-2]),r}function Xd(i,t,e,n,a=null,s=0,r=0){let{float32Array:o,uint16Array:c,uint32Array:l}=Kt,h=i*2;if(ee(h,c)){let d=fe(i,l),f=be(h,c);return _e(i,o,na),n(d,f,!1,r,s+i/8,na)}else{let A=function(C){let{uint16Array:P,uint32Array:N}=Kt,U=C*2;for(;!ee(U,P);)C=le(C),U=C*2;return fe(C,N)},I=function(C){let{uint16Array:P,uint32Array:N}=Kt,U=C*2;for(;!ee(U,P);)C=he(C,N),U=C*2;return fe(C,N)+be(U,P)},d=le(i),f=he(i,l),b=d,_=f,m,x,v,w;if(a&&(v=na,w=Is,_e(b,o,v),_e(_,o,w),m=a(v),x=a(w),x<m)){b=f,_=d;let C=m;m=x,x=C,v=w}v||(v=na,_e(b,o,v));let p=ee(b*2,c),y=e(v,p,m,r+1,s+b/8),S;if(y===2){let C=A(b),N=I(b)-C;S=n(C,N,!0,r+1,s+b/8,v)}else S=y&&Xd(b,t,e,n,a,s,r+1);if(S)return!0;w=Is,_e(_,o,w);let g=ee(_*2,c),M=e(w,g,x,r+1,s+_/8),E;if(M===2){let C=A(_),N=I(_)-C;E=n(C,N,!0,r+1,s+_/8,w)}else E=M&&Xd(_,t,e,n,a,s,r+1);return!!E}}var Kr=new Kt.constructor,Nl=new Kt.constructor,ia=new ea(()=>new on),Rs=new on,Cs=new on,Yd=new on,Jd=new on,Kd=!1;function Km(i,t,e,n){if(Kd)throw new Error("MeshBVH: Recursive calls to bvhcast not supported.");Kd=!0;let a=i._roots,s=t._roots,r,o=0,c=0,l=new Ke().copy(e).invert();for(let h=0,u=a.length;h<u;h++){Kr.setBuffer(a[h]),c=0;let d=ia.getPrimitive();_e(0,Kr.float32Array,d),d.applyMatrix4(l);for(let f=0,b=s.length;f<b&&(Nl.setBuffer(s[f]),r=ti(0,0,e,l,n,o,c,0,0,d),Nl.clearBuffer(),c+=s[f].byteLength/32,!r);f++);if(ia.releasePrimitive(d),Kr.clearBuffer(),o+=a[h].byteLength/32,r)break}return Kd=!1,r}function ti(i,t,e,n,a,s=0,r=0,o=0,c=0,l=null,h=!1){let u,d;h?(u=Nl,d=Kr):(u=Kr,d=Nl);let f=u.float32Array,b=u.uint32Array,_=u.uint16Array,m=d.float32Array,x=d.uint32Array,v=d.uint16Array,w=i*2,p=t*2,y=ee(w,_),S=ee(p,v),g=!1;if(S&&y)h?g=a(fe(t,x),be(t*2,v),fe(i,b),be(i*2,_),c,r+t/8,o,s+i/8):g=a(fe(i,b),be(i*2,_),fe(t,x),be(t*2,v),o,s+i/8,c,r+t/8);else if(S){let M=ia.getPrimitive();_e(t,m,M),M.applyMatrix4(e);let E=le(i),A=he(i,b);_e(E,f,Rs),_e(A,f,Cs);let I=M.intersectsBox(Rs),C=M.intersectsBox(Cs);g=I&&ti(t,E,n,e,a,r,s,c,o+1,M,!h)||C&&ti(t,A,n,e,a,r,s,c,o+1,M,!h),ia.releasePrimitive(M)}else{let M=le(t),E=he(t,x);_e(M,m,Yd),_e(E,m,Jd);let A=l.intersectsBox(Yd),I=l.intersectsBox(Jd);if(A&&I)g=ti(i,M,e,n,a,s,r,o,c+1,l,h)||ti(i,E,e,n,a,s,r,o,c+1,l,h);else if(A)if(y)g=ti(i,M,e,n,a,s,r,o,c+1,l,h);else{let C=ia.getPrimitive();C.copy(Yd).applyMatrix4(e);let P=le(i),N=he(i,b);_e(P,f,Rs),_e(N,f,Cs);let U=C.intersectsBox(Rs),z=C.intersectsBox(Cs);g=U&&ti(M,P,n,e,a,r,s,c,o+1,C,!h)||z&&ti(M,N,n,e,a,r,s,c,o+1,C,!h),ia.releasePrimitive(C)}else if(I)if(y)g=ti(i,E,e,n,a,s,r,o,c+1,l,h);else{let C=ia.getPrimitive();C.copy(Jd).applyMatrix4(e);let P=le(i),N=he(i,b);_e(P,f,Rs),_e(N,f,Cs);let U=C.intersectsBox(Rs),z=C.intersectsBox(Cs);g=U&&ti(E,P,n,e,a,r,s,c,o+1,C,!h)||z&&ti(E,N,n,e,a,r,s,c,o+1,C,!h),ia.releasePrimitive(C)}}return g}var Pl=new class{constructor(){let i=null,t=null,e=null,n=!1;this.root=null,this.buffer=null,this.uint32Array=null,this.uint16Array=null,this.setBVH=(s,r)=>{if(n)throw new Error("BVHTraversalHelper: cannot call setBVH during an active traversal.");this.root=r,this.buffer=i=s._roots[r],this.uint16Array=e=new Uint16Array(i),this.uint32Array=t=new Uint32Array(i)},this.reset=()=>{this.root=null,this.buffer=i=null,this.uint16Array=e=null,this.uint32Array=t=null},this.getRangeStart=s=>{let r=s*2;for(;!ee(r,e);)s=le(s),r=s*2;return fe(s,t)},this.getRangeEnd=s=>{let r=s*2;for(;!ee(r,e);)s=he(s,t),r=s*2;return fe(s,t)+be(r,e)};let a=(s,r,o)=>{let c=r*2,l=ee(c,e);if(!s(o,l,r)&&!l){let u=le(r),d=he(r,t);a(s,u,o+1),a(s,d,o+1)}};this.traverseBuffer=s=>{if(n)throw new Error("BVHTraversalHelper: cannot start a traversal during an active traversal.");n=!0;try{a(s,0,0)}finally{n=!1}},this.traverse=s=>{this.traverseBuffer((r,o,c)=>{if(o){let l=c*2,h=t[c+6],u=e[l+14];return s(r,o,new Float32Array(i,c*4,6),h,u)}else{let l=ws(c,t);return s(r,o,new Float32Array(i,c*4,6),l)}})}}};var Zm=new on,Ns=new Float32Array(6),Ll=class{constructor(){this._roots=null,this.primitiveBuffer=null,this.primitiveBufferStride=null}init(t){t={...Al,...t},"maxLeafSize"in t&&(console.warn('BVH: "maxLeafSize" option has been deprecated. Use "targetLeafSize", instead.'),t={...t,targetLeafSize:t.maxLeafSize}),Ym(this,t)}getRootRanges(){throw new Error("BVH: getRootRanges() not implemented")}writePrimitiveBounds(){throw new Error("BVH: writePrimitiveBounds() not implemented")}writePrimitiveRangeBounds(t,e,n,a){let s=1/0,r=1/0,o=1/0,c=-1/0,l=-1/0,h=-1/0;for(let u=t,d=t+e;u<d;u++){this.writePrimitiveBounds(u,Ns,0);let[f,b,_,m,x,v]=Ns;f<s&&(s=f),m>c&&(c=m),b<r&&(r=b),x>l&&(l=x),_<o&&(o=_),v>h&&(h=v)}return n[a+0]=s,n[a+1]=r,n[a+2]=o,n[a+3]=c,n[a+4]=l,n[a+5]=h,n}computePrimitiveBounds(t,e,n){let a=n.offset||0;for(let s=t,r=t+e;s<r;s++){this.writePrimitiveBounds(s,Ns,0);let[o,c,l,h,u,d]=Ns,f=(o+h)/2,b=(c+u)/2,_=(l+d)/2,m=(h-o)/2,x=(u-c)/2,v=(d-l)/2,w=(s-a)*6;n[w+0]=f,n[w+1]=m+(Math.abs(f)+m)*Ss,n[w+2]=b,n[w+3]=x+(Math.abs(b)+x)*Ss,n[w+4]=_,n[w+5]=v+(Math.abs(_)+v)*Ss}return n}shiftPrimitiveOffsets(t){let e=this._indirectBuffer;if(e)for(let n=0,a=e.length;n<a;n++)e[n]+=t;else{let n=this._roots;for(let a=0;a<n.length;a++){let s=n[a],r=new Uint32Array(s),o=new Uint16Array(s),c=s.byteLength/32;for(let l=0;l<c;l++){let h=8*l,u=2*h;ee(u,o)&&(r[h+6]+=t)}}}}traverse(t,e=0){Pl.setBVH(this,e),Pl.traverse(t),Pl.reset()}refit(){let t=this._roots;for(let e=0,n=t.length;e<n;e++){let a=t[e],s=new Uint32Array(a),r=new Uint16Array(a),o=new Float32Array(a),c=a.byteLength/32;for(let l=c-1;l>=0;l--){let h=l*8,u=h*2;if(ee(u,r)){let f=fe(h,s),b=be(u,r);this.writePrimitiveRangeBounds(f,b,Ns,0),o.set(Ns,h)}else{let f=le(h),b=he(h,s);for(let _=0;_<3;_++){let m=o[f+_],x=o[f+_+3],v=o[b+_],w=o[b+_+3];o[h+_]=m<v?m:v,o[h+_+3]=x>w?x:w}}}}}getBoundingBox(t){return t.makeEmpty(),this._roots.forEach(n=>{_e(0,new Float32Array(n),Zm),t.union(Zm)}),t}shapecast(t){let{boundsTraverseOrder:e,intersectsBounds:n,intersectsRange:a,intersectsPrimitive:s,scratchPrimitive:r,iterate:o}=t;if(a&&s){let u=a;a=(d,f,b,_,m)=>u(d,f,b,_,m)?!0:o(d,f,this,s,b,_,r)}else a||(s?a=(u,d,f,b)=>o(u,d,this,s,f,b,r):a=(u,d,f)=>f);let c=!1,l=0,h=this._roots;for(let u=0,d=h.length;u<d;u++){let f=h[u];if(c=Jm(this,u,n,a,e,l),c)break;l+=f.byteLength/32}return c}bvhcast(t,e,n){let{intersectsRanges:a}=n;return Km(this,t,e,a)}};function Qm(){return typeof SharedArrayBuffer<"u"}function Zd(i){return i.index?i.index.count:i.attributes.position.count}function aa(i){return Zd(i)/3}function VM(i,t=ArrayBuffer){return i>65535?new Uint32Array(new t(4*i)):new Uint16Array(new t(2*i))}function $m(i,t){if(!i.index){let e=i.attributes.position.count,n=t.useSharedArrayBuffer?SharedArrayBuffer:ArrayBuffer,a=VM(e,n);i.setIndex(new ze(a,1));for(let s=0;s<e;s++)a[s]=s}}function HM(i,t,e){let n=Zd(i)/e,a=t||i.drawRange,s=a.start/e,r=(a.start+a.count)/e,o=Math.max(0,s),c=Math.min(n,r)-o;return{offset:Math.floor(o),count:Math.floor(c)}}function GM(i,t){return i.groups.map(e=>({offset:e.start/t,count:e.count/t}))}function Qd(i,t,e){let n=HM(i,t,e),a=GM(i,e);if(!a.length)return[n];let s=[],r=n.offset,o=n.offset+n.count,c=Zd(i)/e,l=[];for(let d of a){let{offset:f,count:b}=d,_=f,m=isFinite(b)?b:c-f,x=f+m;_<o&&x>r&&(l.push({pos:Math.max(r,_),isStart:!0}),l.push({pos:Math.min(o,x),isStart:!1}))}l.sort((d,f)=>d.pos!==f.pos?d.pos-f.pos:d.type==="end"?-1:1);let h=0,u=null;for(let d of l){let f=d.pos;h!==0&&f!==u&&s.push({offset:u,count:f-u}),h+=d.isStart?1:-1,u=f}return s}function WM(i,t){let e=i[i.length-1],n=e.offset+e.count>2**16,a=i.reduce((l,h)=>l+h.count,0),s=n?4:2,r=t?new SharedArrayBuffer(a*s):new ArrayBuffer(a*s),o=n?new Uint32Array(r):new Uint16Array(r),c=0;for(let l=0;l<i.length;l++){let{offset:h,count:u}=i[l];for(let d=0;d<u;d++)o[c+d]=h+d;c+=u}return o}var Dl=class extends Ll{get indirect(){return!!this._indirectBuffer}get primitiveStride(){return null}get primitiveBufferStride(){return this.indirect?1:this.primitiveStride}set primitiveBufferStride(t){}get primitiveBuffer(){return this.indirect?this._indirectBuffer:this.geometry.index.array}set primitiveBuffer(t){}constructor(t,e={}){if(t.isBufferGeometry){if(t.index&&t.index.isInterleavedBufferAttribute)throw new Error("BVH: InterleavedBufferAttribute is not supported for the index attribute.")}else throw new Error("BVH: Only BufferGeometries are supported.");if(e.useSharedArrayBuffer&&!Qm())throw new Error("BVH: SharedArrayBuffer is not available.");super(),this.geometry=t,this.resolvePrimitiveIndex=e.indirect?n=>this._indirectBuffer[n]:n=>n,this.primitiveBuffer=null,this.primitiveBufferStride=null,this._indirectBuffer=null,e={...Al,...e},e[Yr]||this.init(e)}init(t){let{geometry:e,primitiveStride:n}=this;if(t.indirect){let a=Qd(e,t.range,n),s=WM(a,t.useSharedArrayBuffer);this._indirectBuffer=s}else $m(e,t);super.init(t),!e.boundingBox&&t.setBoundingBox&&(e.boundingBox=this.getBoundingBox(new on))}getRootRanges(t){return this.indirect?[{offset:0,count:this._indirectBuffer.length}]:Qd(this.geometry,t,this.primitiveStride)}raycastObject3D(){throw new Error("BVH: raycastObject3D() not implemented")}};var Dn=class{constructor(){this.min=1/0,this.max=-1/0}setFromPointsField(t,e){let n=1/0,a=-1/0;for(let s=0,r=t.length;s<r;s++){let c=t[s][e];n=c<n?c:n,a=c>a?c:a}this.min=n,this.max=a}setFromPoints(t,e){let n=1/0,a=-1/0;for(let s=0,r=e.length;s<r;s++){let o=e[s],c=t.dot(o);n=c<n?c:n,a=c>a?c:a}this.min=n,this.max=a}isSeparated(t){return this.min>t.max||t.min>this.max}};Dn.prototype.setFromBox=(function(){let i=new it;return function(e,n){let a=n.min,s=n.max,r=1/0,o=-1/0;for(let c=0;c<=1;c++)for(let l=0;l<=1;l++)for(let h=0;h<=1;h++){i.x=a.x*c+s.x*(1-c),i.y=a.y*l+s.y*(1-l),i.z=a.z*h+s.z*(1-h);let u=e.dot(i);r=Math.min(u,r),o=Math.max(u,o)}this.min=r,this.max=o}})();var jM=(function(){let i=new it,t=new it,e=new it;return function(a,s,r){let o=a.start,c=i,l=s.start,h=t;e.subVectors(o,l),i.subVectors(a.end,a.start),t.subVectors(s.end,s.start);let u=e.dot(h),d=h.dot(c),f=h.dot(h),b=e.dot(c),m=c.dot(c)*f-d*d,x,v;m!==0?x=(u*d-b*f)/m:x=0,v=(u+x*d)/f,r.x=x,r.y=v}})(),Zr=(function(){let i=new ln,t=new it,e=new it;return function(a,s,r,o){jM(a,s,i);let c=i.x,l=i.y;if(c>=0&&c<=1&&l>=0&&l<=1){a.at(c,r),s.at(l,o);return}else if(c>=0&&c<=1){l<0?s.at(0,o):s.at(1,o),a.closestPointToPoint(o,!0,r);return}else if(l>=0&&l<=1){c<0?a.at(0,r):a.at(1,r),s.closestPointToPoint(r,!0,o);return}else{let h;c<0?h=a.start:h=a.end;let u;l<0?u=s.start:u=s.end;let d=t,f=e;if(a.closestPointToPoint(u,!0,t),s.closestPointToPoint(h,!0,e),d.distanceToSquared(u)<=f.distanceToSquared(h)){r.copy(d),o.copy(u);return}else{r.copy(h),o.copy(f);return}}}})(),tg=(function(){let i=new it,t=new it,e=new xs,n=new zn;return function(s,r){let{radius:o,center:c}=s,{a:l,b:h,c:u}=r;if(n.start=l,n.end=h,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o||(n.start=l,n.end=u,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o)||(n.start=h,n.end=u,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o))return!0;let _=r.getPlane(e);if(Math.abs(_.distanceToPoint(c))<=o){let x=_.projectPoint(c,t);if(r.containsPoint(x))return!0}return!1}})();var XM=["x","y","z"],Ui=1e-15,eg=Ui*Ui;function Hn(i){return Math.abs(i)<Ui}var Ze=class extends Di{constructor(...t){super(...t),this.isExtendedTriangle=!0,this.satAxes=new Array(4).fill().map(()=>new it),this.satBounds=new Array(4).fill().map(()=>new Dn),this.points=[this.a,this.b,this.c],this.plane=new xs,this.isDegenerateIntoSegment=!1,this.isDegenerateIntoPoint=!1,this.degenerateSegment=new zn,this.needsUpdate=!0}intersectsSphere(t){return tg(t,this)}update(){let t=this.a,e=this.b,n=this.c,a=this.points,s=this.satAxes,r=this.satBounds,o=s[0],c=r[0];this.getNormal(o),c.setFromPoints(o,a);let l=s[1],h=r[1];l.subVectors(t,e),h.setFromPoints(l,a);let u=s[2],d=r[2];u.subVectors(e,n),d.setFromPoints(u,a);let f=s[3],b=r[3];f.subVectors(n,t),b.setFromPoints(f,a);let _=l.length(),m=u.length(),x=f.length();this.isDegenerateIntoPoint=!1,this.isDegenerateIntoSegment=!1,_<Ui?m<Ui||x<Ui?this.isDegenerateIntoPoint=!0:(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(t),this.degenerateSegment.end.copy(n)):m<Ui?x<Ui?this.isDegenerateIntoPoint=!0:(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(e),this.degenerateSegment.end.copy(t)):x<Ui&&(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(n),this.degenerateSegment.end.copy(e)),this.plane.setFromNormalAndCoplanarPoint(o,t),this.needsUpdate=!1}};Ze.prototype.closestPointToSegment=(function(){let i=new it,t=new it,e=new zn;return function(a,s=null,r=null){this.needsUpdate&&this.update();let{start:o,end:c}=a,l=this.points,h,u=1/0,d=this.plane.distanceToPoint(o),f=this.plane.distanceToPoint(c);if(d*f<0&&this.plane.intersectLine(a,i)!==null&&this.containsPoint(i))return s&&s.copy(i),r&&r.copy(i),0;for(let b=0;b<3;b++){let _=(b+1)%3;e.start.copy(l[b]),e.end.copy(l[_]),Zr(e,a,i,t),h=i.distanceToSquared(t),h<u&&(u=h,s&&s.copy(i),r&&r.copy(t))}return this.closestPointToPoint(o,i),h=o.distanceToSquared(i),h<u&&(u=h,s&&s.copy(i),r&&r.copy(o)),this.closestPointToPoint(c,i),h=c.distanceToSquared(i),h<u&&(u=h,s&&s.copy(i),r&&r.copy(c)),Math.sqrt(u)}})();Ze.prototype.intersectsTriangle=(function(){let i=new Ze,t=new Dn,e=new Dn,n=new it,a=new it,s=new it,r=new it,o=new zn,c=new zn,l=new it,h=new ln,u=new ln;function d(w,p,y,S){let g=n;!w.isDegenerateIntoPoint&&!w.isDegenerateIntoSegment?g.copy(w.plane.normal):g.copy(p.plane.normal);let M=w.satBounds,E=w.satAxes;for(let C=1;C<4;C++){let P=M[C],N=E[C];if(t.setFromPoints(N,p.points),P.isSeparated(t)||(r.copy(g).cross(N),t.setFromPoints(r,w.points),e.setFromPoints(r,p.points),t.isSeparated(e)))return!1}let A=p.satBounds,I=p.satAxes;for(let C=1;C<4;C++){let P=A[C],N=I[C];if(t.setFromPoints(N,w.points),P.isSeparated(t)||(r.crossVectors(g,N),t.setFromPoints(r,w.points),e.setFromPoints(r,p.points),t.isSeparated(e)))return!1}return y&&(S||console.warn("ExtendedTriangle.intersectsTriangle: Triangles are coplanar which does not support an output edge. Setting edge to 0, 0, 0."),y.start.set(0,0,0),y.end.set(0,0,0)),!0}function f(w,p,y,S,g,M,E,A,I,C,P){let N=E/(E-A);C.x=S+(g-S)*N,P.start.subVectors(p,w).multiplyScalar(N).add(w),N=E/(E-I),C.y=S+(M-S)*N,P.end.subVectors(y,w).multiplyScalar(N).add(w)}function b(w,p,y,S,g,M,E,A,I,C,P){if(g>0)f(w.c,w.a,w.b,S,p,y,I,E,A,C,P);else if(M>0)f(w.b,w.a,w.c,y,p,S,A,E,I,C,P);else if(A*I>0||E!=0)f(w.a,w.b,w.c,p,y,S,E,A,I,C,P);else if(A!=0)f(w.b,w.a,w.c,y,p,S,A,E,I,C,P);else if(I!=0)f(w.c,w.a,w.b,S,p,y,I,E,A,C,P);else return!0;return!1}function _(w,p,y,S){let g=p.degenerateSegment,M=w.plane.distanceToPoint(g.start),E=w.plane.distanceToPoint(g.end);return Hn(M)?Hn(E)?d(w,p,y,S):(y&&(y.start.copy(g.start),y.end.copy(g.start)),w.containsPoint(g.start)):Hn(E)?(y&&(y.start.copy(g.end),y.end.copy(g.end)),w.containsPoint(g.end)):w.plane.intersectLine(g,n)!=null?(y&&(y.start.copy(n),y.end.copy(n)),w.containsPoint(n)):!1}function m(w,p,y){let S=p.a;return Hn(w.plane.distanceToPoint(S))&&w.containsPoint(S)?(y&&(y.start.copy(S),y.end.copy(S)),!0):!1}function x(w,p,y){let S=w.degenerateSegment,g=p.a;return S.closestPointToPoint(g,!0,n),g.distanceToSquared(n)<eg?(y&&(y.start.copy(g),y.end.copy(g)),!0):!1}function v(w,p,y,S){if(w.isDegenerateIntoSegment)if(p.isDegenerateIntoSegment){let g=w.degenerateSegment,M=p.degenerateSegment,E=a,A=s;g.delta(E),M.delta(A);let I=n.subVectors(M.start,g.start),C=E.x*A.y-E.y*A.x;if(Hn(C))return!1;let P=(I.x*A.y-I.y*A.x)/C,N=-(E.x*I.y-E.y*I.x)/C;if(P<0||P>1||N<0||N>1)return!1;let U=g.start.z+E.z*P,z=M.start.z+A.z*N;return Hn(U-z)?(y&&(y.start.copy(g.start).addScaledVector(E,P),y.end.copy(g.start).addScaledVector(E,P)),!0):!1}else return p.isDegenerateIntoPoint?x(w,p,y):_(p,w,y,S);else{if(w.isDegenerateIntoPoint)return p.isDegenerateIntoPoint?p.a.distanceToSquared(w.a)<eg?(y&&(y.start.copy(w.a),y.end.copy(w.a)),!0):!1:p.isDegenerateIntoSegment?x(p,w,y):m(p,w,y);if(p.isDegenerateIntoPoint)return m(w,p,y);if(p.isDegenerateIntoSegment)return _(w,p,y,S)}}return function(p,y=null,S=!1){this.needsUpdate&&this.update(),p.isExtendedTriangle?p.needsUpdate&&p.update():(i.copy(p),i.update(),p=i);let g=v(this,p,y,S);if(g!==void 0)return g;let M=this.plane,E=p.plane,A=E.distanceToPoint(this.a),I=E.distanceToPoint(this.b),C=E.distanceToPoint(this.c);Hn(A)&&(A=0),Hn(I)&&(I=0),Hn(C)&&(C=0);let P=A*I,N=A*C;if(P>0&&N>0)return!1;let U=M.distanceToPoint(p.a),z=M.distanceToPoint(p.b),F=M.distanceToPoint(p.c);Hn(U)&&(U=0),Hn(z)&&(z=0),Hn(F)&&(F=0);let K=U*z,H=U*F;if(K>0&&H>0)return!1;a.copy(M.normal),s.copy(E.normal);let J=a.cross(s),tt=0,ft=Math.abs(J.x),Ct=Math.abs(J.y);Ct>ft&&(ft=Ct,tt=1),Math.abs(J.z)>ft&&(tt=2);let st=XM[tt],xt=this.a[st],It=this.b[st],mt=this.c[st],Ot=p.a[st],Me=p.b[st],Lt=p.c[st];if(b(this,xt,It,mt,P,N,A,I,C,h,o))return d(this,p,y,S);if(b(p,Ot,Me,Lt,K,H,U,z,F,u,c))return d(this,p,y,S);if(h.y<h.x){let $t=h.y;h.y=h.x,h.x=$t,l.copy(o.start),o.start.copy(o.end),o.end.copy(l)}if(u.y<u.x){let $t=u.y;u.y=u.x,u.x=$t,l.copy(c.start),c.start.copy(c.end),c.end.copy(l)}return h.y<u.x||u.y<h.x?!1:(y&&(u.x>h.x?y.start.copy(c.start):y.start.copy(o.start),u.y<h.y?y.end.copy(c.end):y.end.copy(o.end)),!0)}})();Ze.prototype.distanceToPoint=(function(){let i=new it;return function(e){return this.closestPointToPoint(e,i),e.distanceTo(i)}})();Ze.prototype.distanceToTriangle=(function(){let i=new it,t=new it,e=["a","b","c"],n=new zn,a=new zn;return function(r,o=null,c=null){let l=o||c?n:null;if(this.intersectsTriangle(r,l,!0))return(o||c)&&(o&&l.getCenter(o),c&&l.getCenter(c)),0;let h=1/0;for(let u=0;u<3;u++){let d,f=e[u],b=r[f];this.closestPointToPoint(b,i),d=b.distanceToSquared(i),d<h&&(h=d,o&&o.copy(i),c&&c.copy(b));let _=this[f];r.closestPointToPoint(_,i),d=_.distanceToSquared(i),d<h&&(h=d,o&&o.copy(_),c&&c.copy(i))}for(let u=0;u<3;u++){let d=e[u],f=e[(u+1)%3];n.set(this[d],this[f]);for(let b=0;b<3;b++){let _=e[b],m=e[(b+1)%3];a.set(r[_],r[m]),Zr(n,a,i,t);let x=i.distanceToSquared(t);x<h&&(h=x,o&&o.copy(i),c&&c.copy(t))}}return Math.sqrt(h)}})();var Ie=class{constructor(t,e,n){this.isOrientedBox=!0,this.min=new it,this.max=new it,this.matrix=new Ke,this.invMatrix=new Ke,this.points=new Array(8).fill().map(()=>new it),this.satAxes=new Array(3).fill().map(()=>new it),this.satBounds=new Array(3).fill().map(()=>new Dn),this.alignedSatBounds=new Array(3).fill().map(()=>new Dn),this.needsUpdate=!1,t&&this.min.copy(t),e&&this.max.copy(e),n&&this.matrix.copy(n)}set(t,e,n){this.min.copy(t),this.max.copy(e),this.matrix.copy(n),this.needsUpdate=!0}copy(t){this.min.copy(t.min),this.max.copy(t.max),this.matrix.copy(t.matrix),this.needsUpdate=!0}};Ie.prototype.update=(function(){return function(){let t=this.matrix,e=this.min,n=this.max,a=this.points;for(let l=0;l<=1;l++)for(let h=0;h<=1;h++)for(let u=0;u<=1;u++){let d=1*l|2*h|4*u,f=a[d];f.x=l?n.x:e.x,f.y=h?n.y:e.y,f.z=u?n.z:e.z,f.applyMatrix4(t)}let s=this.satBounds,r=this.satAxes,o=a[0];for(let l=0;l<3;l++){let h=r[l],u=s[l],d=1<<l,f=a[d];h.subVectors(o,f),u.setFromPoints(h,a)}let c=this.alignedSatBounds;c[0].setFromPointsField(a,"x"),c[1].setFromPointsField(a,"y"),c[2].setFromPointsField(a,"z"),this.invMatrix.copy(this.matrix).invert(),this.needsUpdate=!1}})();Ie.prototype.intersectsBox=(function(){let i=new Dn;return function(e){this.needsUpdate&&this.update();let n=e.min,a=e.max,s=this.satBounds,r=this.satAxes,o=this.alignedSatBounds;if(i.min=n.x,i.max=a.x,o[0].isSeparated(i)||(i.min=n.y,i.max=a.y,o[1].isSeparated(i))||(i.min=n.z,i.max=a.z,o[2].isSeparated(i)))return!1;for(let c=0;c<3;c++){let l=r[c],h=s[c];if(i.setFromBox(l,e),h.isSeparated(i))return!1}return!0}})();Ie.prototype.intersectsTriangle=(function(){let i=new Ze,t=new Array(3),e=new Dn,n=new Dn,a=new it;return function(r){this.needsUpdate&&this.update(),r.isExtendedTriangle?r.needsUpdate&&r.update():(i.copy(r),i.update(),r=i);let o=this.satBounds,c=this.satAxes;t[0]=r.a,t[1]=r.b,t[2]=r.c;for(let d=0;d<3;d++){let f=o[d],b=c[d];if(e.setFromPoints(b,t),f.isSeparated(e))return!1}let l=r.satBounds,h=r.satAxes,u=this.points;for(let d=0;d<3;d++){let f=l[d],b=h[d];if(e.setFromPoints(b,u),f.isSeparated(e))return!1}for(let d=0;d<3;d++){let f=c[d];for(let b=0;b<4;b++){let _=h[b];if(a.crossVectors(f,_),e.setFromPoints(a,t),n.setFromPoints(a,u),e.isSeparated(n))return!1}}return!0}})();Ie.prototype.closestPointToPoint=(function(){return function(t,e){return this.needsUpdate&&this.update(),e.copy(t).applyMatrix4(this.invMatrix).clamp(this.min,this.max).applyMatrix4(this.matrix),e}})();Ie.prototype.distanceToPoint=(function(){let i=new it;return function(e){return this.closestPointToPoint(e,i),e.distanceTo(i)}})();Ie.prototype.distanceToBox=(function(){let i=["x","y","z"],t=new Array(12).fill().map(()=>new zn),e=new Array(12).fill().map(()=>new zn),n=new it,a=new it;return function(r,o=0,c=null,l=null){if(this.needsUpdate&&this.update(),this.intersectsBox(r))return(c||l)&&(r.getCenter(a),this.closestPointToPoint(a,n),r.closestPointToPoint(n,a),c&&c.copy(n),l&&l.copy(a)),0;let h=o*o,u=r.min,d=r.max,f=this.points,b=1/0;for(let m=0;m<8;m++){let x=f[m];a.copy(x).clamp(u,d);let v=x.distanceToSquared(a);if(v<b&&(b=v,c&&c.copy(x),l&&l.copy(a),v<h))return Math.sqrt(v)}let _=0;for(let m=0;m<3;m++)for(let x=0;x<=1;x++)for(let v=0;v<=1;v++){let w=(m+1)%3,p=(m+2)%3,y=x<<w|v<<p,S=1<<m|x<<w|v<<p,g=f[y],M=f[S];t[_].set(g,M);let A=i[m],I=i[w],C=i[p],P=e[_],N=P.start,U=P.end;N[A]=u[A],N[I]=x?u[I]:d[I],N[C]=v?u[C]:d[C],U[A]=d[A],U[I]=x?u[I]:d[I],U[C]=v?u[C]:d[C],_++}for(let m=0;m<=1;m++)for(let x=0;x<=1;x++)for(let v=0;v<=1;v++){a.x=m?d.x:u.x,a.y=x?d.y:u.y,a.z=v?d.z:u.z,this.closestPointToPoint(a,n);let w=a.distanceToSquared(n);if(w<b&&(b=w,c&&c.copy(n),l&&l.copy(a),w<h))return Math.sqrt(w)}for(let m=0;m<12;m++){let x=t[m];for(let v=0;v<12;v++){let w=e[v];Zr(x,w,n,a);let p=n.distanceToSquared(a);if(p<b&&(b=p,c&&c.copy(n),l&&l.copy(a),p<h))return Math.sqrt(p)}}return Math.sqrt(b)}})();var $d=class extends ea{constructor(){super(()=>new Ze)}},vn=new $d;var Qr=new it,tu=new it;function ng(i,t,e={},n=0,a=1/0){let s=n*n,r=a*a,o=1/0,c=null;if(i.shapecast({boundsTraverseOrder:h=>(Qr.copy(t).clamp(h.min,h.max),Qr.distanceToSquared(t)),intersectsBounds:(h,u,d)=>d<o&&d<r,intersectsTriangle:(h,u)=>{h.closestPointToPoint(t,Qr);let d=t.distanceToSquared(Qr);return d<o&&(tu.copy(Qr),o=d,c=u),d<s}}),o===1/0)return null;let l=Math.sqrt(o);return e.point?e.point.copy(tu):e.point=tu.clone(),e.distance=l,e.faceIndex=c,e}var Ul=parseInt(Ld)>=169,qM=parseInt(Ld)<=161,Ea=new it,Ta=new it,Ia=new it,Ol=new ln,Fl=new ln,Bl=new ln,ig=new it,ag=new it,sg=new it,$r=new it;function YM(i,t,e,n,a,s,r,o){let c;if(s===ul?c=i.intersectTriangle(n,e,t,!0,a):c=i.intersectTriangle(t,e,n,s!==Li,a),c===null)return null;let l=i.origin.distanceTo(a);return l<r||l>o?null:{distance:l,point:a.clone()}}function rg(i,t,e,n,a,s,r,o,c,l,h){Ea.fromBufferAttribute(t,s),Ta.fromBufferAttribute(t,r),Ia.fromBufferAttribute(t,o);let u=YM(i,Ea,Ta,Ia,$r,c,l,h);if(u){if(n){Ol.fromBufferAttribute(n,s),Fl.fromBufferAttribute(n,r),Bl.fromBufferAttribute(n,o),u.uv=new ln;let f=Di.getInterpolation($r,Ea,Ta,Ia,Ol,Fl,Bl,u.uv);Ul||(u.uv=f)}if(a){Ol.fromBufferAttribute(a,s),Fl.fromBufferAttribute(a,r),Bl.fromBufferAttribute(a,o),u.uv1=new ln;let f=Di.getInterpolation($r,Ea,Ta,Ia,Ol,Fl,Bl,u.uv1);Ul||(u.uv1=f),qM&&(u.uv2=u.uv1)}if(e){ig.fromBufferAttribute(e,s),ag.fromBufferAttribute(e,r),sg.fromBufferAttribute(e,o),u.normal=new it;let f=Di.getInterpolation($r,Ea,Ta,Ia,ig,ag,sg,u.normal);u.normal.dot(i.direction)>0&&u.normal.multiplyScalar(-1),Ul||(u.normal=f)}let d={a:s,b:r,c:o,normal:new it,materialIndex:0};if(Di.getNormal(Ea,Ta,Ia,d.normal),u.face=d,u.faceIndex=s,Ul){let f=new it;Di.getBarycoord($r,Ea,Ta,Ia,f),u.barycoord=f}}return u}function og(i){return i&&i.isMaterial?i.side:i}function Ps(i,t,e,n,a,s,r){let o=n*3,c=o+0,l=o+1,h=o+2,{index:u,groups:d}=i;i.index&&(c=u.getX(c),l=u.getX(l),h=u.getX(h));let{position:f,normal:b,uv:_,uv1:m}=i.attributes;if(Array.isArray(t)){let x=n*3;for(let v=0,w=d.length;v<w;v++){let{start:p,count:y,materialIndex:S}=d[v];if(x>=p&&x<p+y){let g=og(t[S]),M=rg(e,f,b,_,m,c,l,h,g,s,r);if(M)if(M.faceIndex=n,M.face.materialIndex=S,a)a.push(M);else return M}}}else{let x=og(t),v=rg(e,f,b,_,m,c,l,h,x,s,r);if(v)if(v.faceIndex=n,v.face.materialIndex=0,a)a.push(v);else return v}return null}function ve(i,t,e,n){let a=i.a,s=i.b,r=i.c,o=t,c=t+1,l=t+2;e&&(o=e.getX(o),c=e.getX(c),l=e.getX(l)),a.x=n.getX(o),a.y=n.getY(o),a.z=n.getZ(o),s.x=n.getX(c),s.y=n.getY(c),s.z=n.getZ(c),r.x=n.getX(l),r.y=n.getY(l),r.z=n.getZ(l)}function cg(i,t,e,n,a,s,r,o){let{geometry:c,_indirectBuffer:l}=i;for(let h=n,u=n+a;h<u;h++)Ps(c,t,e,h,s,r,o)}function lg(i,t,e,n,a,s,r){let{geometry:o,_indirectBuffer:c}=i,l=1/0,h=null;for(let u=n,d=n+a;u<d;u++){let f;f=Ps(o,t,e,u,null,s,r),f&&f.distance<l&&(h=f,l=f.distance)}return h}function hg(i,t,e,n,a,s,r){let{geometry:o}=e,{index:c}=o,l=o.attributes.position;for(let h=i,u=t+i;h<u;h++){let d;if(d=h,ve(r,d*3,c,l),r.needsUpdate=!0,n(r,d,a,s))return!0}return!1}function dg(i,t=null){t&&Array.isArray(t)&&(t=new Set(t));let e=i.geometry,n=e.index?e.index.array:null,a=e.attributes.position,s,r,o,c,l=0,h=i._roots;for(let d=0,f=h.length;d<f;d++)s=h[d],r=new Uint32Array(s),o=new Uint16Array(s),c=new Float32Array(s),u(0,l),l+=s.byteLength;function u(d,f,b=!1){let _=d*2;if(ee(_,o)){let m=fe(d,r),x=be(_,o),v=1/0,w=1/0,p=1/0,y=-1/0,S=-1/0,g=-1/0;for(let M=3*m,E=3*(m+x);M<E;M++){let A=n[M],I=a.getX(A),C=a.getY(A),P=a.getZ(A);I<v&&(v=I),I>y&&(y=I),C<w&&(w=C),C>S&&(S=C),P<p&&(p=P),P>g&&(g=P)}return c[d+0]!==v||c[d+1]!==w||c[d+2]!==p||c[d+3]!==y||c[d+4]!==S||c[d+5]!==g?(c[d+0]=v,c[d+1]=w,c[d+2]=p,c[d+3]=y,c[d+4]=S,c[d+5]=g,!0):!1}else{let m=le(d),x=he(d,r),v=b,w=!1,p=!1;if(t){if(!v){let A=m/8+f/32,I=x/8+f/32;w=t.has(A),p=t.has(I),v=!w&&!p}}else w=!0,p=!0;let y=v||w,S=v||p,g=!1;y&&(g=u(m,f,v));let M=!1;S&&(M=u(x,f,v));let E=g||M;if(E)for(let A=0;A<3;A++){let I=m+A,C=x+A,P=c[I],N=c[I+3],U=c[C],z=c[C+3];c[d+A]=P<U?P:U,c[d+A+3]=N>z?N:z}return E}}}function hn(i,t,e,n,a){let s,r,o,c,l,h,u=1/e.direction.x,d=1/e.direction.y,f=1/e.direction.z,b=e.origin.x,_=e.origin.y,m=e.origin.z,x=t[i],v=t[i+3],w=t[i+1],p=t[i+3+1],y=t[i+2],S=t[i+3+2];return u>=0?(s=(x-b)*u,r=(v-b)*u):(s=(v-b)*u,r=(x-b)*u),d>=0?(o=(w-_)*d,c=(p-_)*d):(o=(p-_)*d,c=(w-_)*d),s>c||o>r||((o>s||isNaN(s))&&(s=o),(c<r||isNaN(r))&&(r=c),f>=0?(l=(y-m)*f,h=(S-m)*f):(l=(S-m)*f,h=(y-m)*f),s>h||l>r)?!1:((l>s||s!==s)&&(s=l),(h<r||r!==r)&&(r=h),s<=a&&r>=n)}function ug(i,t,e,n,a,s,r,o){let{geometry:c,_indirectBuffer:l}=i;for(let h=n,u=n+a;h<u;h++){let d=l?l[h]:h;Ps(c,t,e,d,s,r,o)}}function fg(i,t,e,n,a,s,r){let{geometry:o,_indirectBuffer:c}=i,l=1/0,h=null;for(let u=n,d=n+a;u<d;u++){let f;f=Ps(o,t,e,c?c[u]:u,null,s,r),f&&f.distance<l&&(h=f,l=f.distance)}return h}function pg(i,t,e,n,a,s,r){let{geometry:o}=e,{index:c}=o,l=o.attributes.position;for(let h=i,u=t+i;h<u;h++){let d;if(d=e.resolveTriangleIndex(h),ve(r,d*3,c,l),r.needsUpdate=!0,n(r,d,a,s))return!0}return!1}function mg(i,t,e,n,a,s,r){Kt.setBuffer(i._roots[t]),hn(0,Kt.float32Array,n,s,r)&&eu(0,i,e,n,a,s,r),Kt.clearBuffer()}function eu(i,t,e,n,a,s,r){let{float32Array:o,uint16Array:c,uint32Array:l}=Kt,h=i*2;if(ee(h,c)){let d=fe(i,l),f=be(h,c);cg(t,e,n,d,f,a,s,r)}else{let d=le(i);hn(d,o,n,s,r)&&eu(d,t,e,n,a,s,r);let f=he(i,l);hn(f,o,n,s,r)&&eu(f,t,e,n,a,s,r)}}var JM=["x","y","z"];function gg(i,t,e,n,a,s){Kt.setBuffer(i._roots[t]);let r=null;return hn(0,Kt.float32Array,n,a,s)&&(r=nu(0,i,e,n,a,s)),Kt.clearBuffer(),r}function nu(i,t,e,n,a,s){let{float32Array:r,uint16Array:o,uint32Array:c}=Kt,l=i*2;if(ee(l,o)){let u=fe(i,c),d=be(l,o);return lg(t,e,n,u,d,a,s)}else{let u=ws(i,c),d=JM[u],b=n.direction[d]>=0,_,m;b?(_=le(i),m=he(i,c)):(_=he(i,c),m=le(i));let v=hn(_,r,n,a,s)?nu(_,t,e,n,a,s):null;if(v){let y=v.point[d];if(b?y<=r[m+u]:y>=r[m+u+3])return v}let p=hn(m,r,n,a,s)?nu(m,t,e,n,a,s):null;return v&&p?v.distance<=p.distance?v:p:v||p||null}}var kl=new on,Ls=new Ze,Ds=new Ze,to=new Ke,bg=new Ie,zl=new Ie;function xg(i,t,e,n){Kt.setBuffer(i._roots[t]);let a=iu(0,i,e,n);return Kt.clearBuffer(),a}function iu(i,t,e,n,a=null){let{float32Array:s,uint16Array:r,uint32Array:o}=Kt,c=i*2;if(a===null&&(e.boundingBox||e.computeBoundingBox(),bg.set(e.boundingBox.min,e.boundingBox.max,n),a=bg),ee(c,r)){let h=t.geometry,u=h.index,d=h.attributes.position,f=e.index,b=e.attributes.position,_=fe(i,o),m=be(c,r);if(to.copy(n).invert(),e.boundsTree)return _e(i,s,zl),zl.matrix.copy(to),zl.needsUpdate=!0,e.boundsTree.shapecast({intersectsBounds:v=>zl.intersectsBox(v),intersectsTriangle:v=>{v.a.applyMatrix4(n),v.b.applyMatrix4(n),v.c.applyMatrix4(n),v.needsUpdate=!0;for(let w=_*3,p=(m+_)*3;w<p;w+=3)if(ve(Ds,w,u,d),Ds.needsUpdate=!0,v.intersectsTriangle(Ds))return!0;return!1}});{let x=aa(e);for(let v=_*3,w=(m+_)*3;v<w;v+=3){ve(Ls,v,u,d),Ls.a.applyMatrix4(to),Ls.b.applyMatrix4(to),Ls.c.applyMatrix4(to),Ls.needsUpdate=!0;for(let p=0,y=x*3;p<y;p+=3)if(ve(Ds,p,f,b),Ds.needsUpdate=!0,Ls.intersectsTriangle(Ds))return!0}}}else{let h=le(i),u=he(i,o);return _e(h,s,kl),!!(a.intersectsBox(kl)&&iu(h,t,e,n,a)||(_e(u,s,kl),a.intersectsBox(kl)&&iu(u,t,e,n,a)))}}var Vl=new Ke,au=new Ie,eo=new Ie,KM=new it,ZM=new it,QM=new it,$M=new it;function yg(i,t,e,n={},a={},s=0,r=1/0){t.boundingBox||t.computeBoundingBox(),au.set(t.boundingBox.min,t.boundingBox.max,e),au.needsUpdate=!0;let o=i.geometry,c=o.attributes.position,l=o.index,h=t.attributes.position,u=t.index,d=vn.getPrimitive(),f=vn.getPrimitive(),b=KM,_=ZM,m=null,x=null;a&&(m=QM,x=$M);let v=1/0,w=null,p=null;return Vl.copy(e).invert(),eo.matrix.copy(Vl),i.shapecast({boundsTraverseOrder:y=>au.distanceToBox(y),intersectsBounds:(y,S,g)=>g<v&&g<r?(S&&(eo.min.copy(y.min),eo.max.copy(y.max),eo.needsUpdate=!0),!0):!1,intersectsRange:(y,S)=>{if(t.boundsTree)return t.boundsTree.shapecast({boundsTraverseOrder:M=>eo.distanceToBox(M),intersectsBounds:(M,E,A)=>A<v&&A<r,intersectsRange:(M,E)=>{for(let A=M,I=M+E;A<I;A++){ve(f,3*A,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let C=y,P=y+S;C<P;C++){ve(d,3*C,l,c),d.needsUpdate=!0;let N=d.distanceToTriangle(f,b,m);if(N<v&&(_.copy(b),x&&x.copy(m),v=N,w=C,p=A),N<s)return!0}}}});{let g=aa(t);for(let M=0,E=g;M<E;M++){ve(f,3*M,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let A=y,I=y+S;A<I;A++){ve(d,3*A,l,c),d.needsUpdate=!0;let C=d.distanceToTriangle(f,b,m);if(C<v&&(_.copy(b),x&&x.copy(m),v=C,w=A,p=M),C<s)return!0}}}}}),vn.releasePrimitive(d),vn.releasePrimitive(f),v===1/0?null:(n.point?n.point.copy(_):n.point=_.clone(),n.distance=v,n.faceIndex=w,a&&(a.point?a.point.copy(x):a.point=x.clone(),a.point.applyMatrix4(Vl),_.applyMatrix4(Vl),a.distance=_.sub(a.point).length(),a.faceIndex=p),n)}function _g(i,t=null){t&&Array.isArray(t)&&(t=new Set(t));let e=i.geometry,n=e.index?e.index.array:null,a=e.attributes.position,s,r,o,c,l=0,h=i._roots;for(let d=0,f=h.length;d<f;d++)s=h[d],r=new Uint32Array(s),o=new Uint16Array(s),c=new Float32Array(s),u(0,l),l+=s.byteLength;function u(d,f,b=!1){let _=d*2;if(ee(_,o)){let m=fe(d,r),x=be(_,o),v=1/0,w=1/0,p=1/0,y=-1/0,S=-1/0,g=-1/0;for(let M=m,E=m+x;M<E;M++){let A=3*i.resolveTriangleIndex(M);for(let I=0;I<3;I++){let C=A+I;C=n?n[C]:C;let P=a.getX(C),N=a.getY(C),U=a.getZ(C);P<v&&(v=P),P>y&&(y=P),N<w&&(w=N),N>S&&(S=N),U<p&&(p=U),U>g&&(g=U)}}return c[d+0]!==v||c[d+1]!==w||c[d+2]!==p||c[d+3]!==y||c[d+4]!==S||c[d+5]!==g?(c[d+0]=v,c[d+1]=w,c[d+2]=p,c[d+3]=y,c[d+4]=S,c[d+5]=g,!0):!1}else{let m=le(d),x=he(d,r),v=b,w=!1,p=!1;if(t){if(!v){let A=m/8+f/32,I=x/8+f/32;w=t.has(A),p=t.has(I),v=!w&&!p}}else w=!0,p=!0;let y=v||w,S=v||p,g=!1;y&&(g=u(m,f,v));let M=!1;S&&(M=u(x,f,v));let E=g||M;if(E)for(let A=0;A<3;A++){let I=m+A,C=x+A,P=c[I],N=c[I+3],U=c[C],z=c[C+3];c[d+A]=P<U?P:U,c[d+A+3]=N>z?N:z}return E}}}function vg(i,t,e,n,a,s,r){Kt.setBuffer(i._roots[t]),hn(0,Kt.float32Array,n,s,r)&&su(0,i,e,n,a,s,r),Kt.clearBuffer()}function su(i,t,e,n,a,s,r){let{float32Array:o,uint16Array:c,uint32Array:l}=Kt,h=i*2;if(ee(h,c)){let d=fe(i,l),f=be(h,c);ug(t,e,n,d,f,a,s,r)}else{let d=le(i);hn(d,o,n,s,r)&&su(d,t,e,n,a,s,r);let f=he(i,l);hn(f,o,n,s,r)&&su(f,t,e,n,a,s,r)}}var tS=["x","y","z"];function Mg(i,t,e,n,a,s){Kt.setBuffer(i._roots[t]);let r=null;return hn(0,Kt.float32Array,n,a,s)&&(r=ru(0,i,e,n,a,s)),Kt.clearBuffer(),r}function ru(i,t,e,n,a,s){let{float32Array:r,uint16Array:o,uint32Array:c}=Kt,l=i*2;if(ee(l,o)){let u=fe(i,c),d=be(l,o);return fg(t,e,n,u,d,a,s)}else{let u=ws(i,c),d=tS[u],b=n.direction[d]>=0,_,m;b?(_=le(i),m=he(i,c)):(_=he(i,c),m=le(i));let v=hn(_,r,n,a,s)?ru(_,t,e,n,a,s):null;if(v){let y=v.point[d];if(b?y<=r[m+u]:y>=r[m+u+3])return v}let p=hn(m,r,n,a,s)?ru(m,t,e,n,a,s):null;return v&&p?v.distance<=p.distance?v:p:v||p||null}}var Hl=new on,Us=new Ze,Os=new Ze,no=new Ke,Sg=new Ie,Gl=new Ie;function wg(i,t,e,n){Kt.setBuffer(i._roots[t]);let a=ou(0,i,e,n);return Kt.clearBuffer(),a}function ou(i,t,e,n,a=null){let{float32Array:s,uint16Array:r,uint32Array:o}=Kt,c=i*2;if(a===null&&(e.boundingBox||e.computeBoundingBox(),Sg.set(e.boundingBox.min,e.boundingBox.max,n),a=Sg),ee(c,r)){let h=t.geometry,u=h.index,d=h.attributes.position,f=e.index,b=e.attributes.position,_=fe(i,o),m=be(c,r);if(no.copy(n).invert(),e.boundsTree)return _e(i,s,Gl),Gl.matrix.copy(no),Gl.needsUpdate=!0,e.boundsTree.shapecast({intersectsBounds:v=>Gl.intersectsBox(v),intersectsTriangle:v=>{v.a.applyMatrix4(n),v.b.applyMatrix4(n),v.c.applyMatrix4(n),v.needsUpdate=!0;for(let w=_,p=m+_;w<p;w++)if(ve(Os,3*t.resolveTriangleIndex(w),u,d),Os.needsUpdate=!0,v.intersectsTriangle(Os))return!0;return!1}});{let x=aa(e);for(let v=_,w=m+_;v<w;v++){let p=t.resolveTriangleIndex(v);ve(Us,3*p,u,d),Us.a.applyMatrix4(no),Us.b.applyMatrix4(no),Us.c.applyMatrix4(no),Us.needsUpdate=!0;for(let y=0,S=x*3;y<S;y+=3)if(ve(Os,y,f,b),Os.needsUpdate=!0,Us.intersectsTriangle(Os))return!0}}}else{let h=le(i),u=he(i,o);return _e(h,s,Hl),!!(a.intersectsBox(Hl)&&ou(h,t,e,n,a)||(_e(u,s,Hl),a.intersectsBox(Hl)&&ou(u,t,e,n,a)))}}var Wl=new Ke,cu=new Ie,io=new Ie,eS=new it,nS=new it,iS=new it,aS=new it;function Ag(i,t,e,n={},a={},s=0,r=1/0){t.boundingBox||t.computeBoundingBox(),cu.set(t.boundingBox.min,t.boundingBox.max,e),cu.needsUpdate=!0;let o=i.geometry,c=o.attributes.position,l=o.index,h=t.attributes.position,u=t.index,d=vn.getPrimitive(),f=vn.getPrimitive(),b=eS,_=nS,m=null,x=null;a&&(m=iS,x=aS);let v=1/0,w=null,p=null;return Wl.copy(e).invert(),io.matrix.copy(Wl),i.shapecast({boundsTraverseOrder:y=>cu.distanceToBox(y),intersectsBounds:(y,S,g)=>g<v&&g<r?(S&&(io.min.copy(y.min),io.max.copy(y.max),io.needsUpdate=!0),!0):!1,intersectsRange:(y,S)=>{if(t.boundsTree){let g=t.boundsTree;return g.shapecast({boundsTraverseOrder:M=>io.distanceToBox(M),intersectsBounds:(M,E,A)=>A<v&&A<r,intersectsRange:(M,E)=>{for(let A=M,I=M+E;A<I;A++){let C=g.resolveTriangleIndex(A);ve(f,3*C,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let P=y,N=y+S;P<N;P++){let U=i.resolveTriangleIndex(P);ve(d,3*U,l,c),d.needsUpdate=!0;let z=d.distanceToTriangle(f,b,m);if(z<v&&(_.copy(b),x&&x.copy(m),v=z,w=P,p=A),z<s)return!0}}}})}else{let g=aa(t);for(let M=0,E=g;M<E;M++){ve(f,3*M,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let A=y,I=y+S;A<I;A++){let C=i.resolveTriangleIndex(A);ve(d,3*C,l,c),d.needsUpdate=!0;let P=d.distanceToTriangle(f,b,m);if(P<v&&(_.copy(b),x&&x.copy(m),v=P,w=A,p=M),P<s)return!0}}}}}),vn.releasePrimitive(d),vn.releasePrimitive(f),v===1/0?null:(n.point?n.point.copy(_):n.point=_.clone(),n.distance=v,n.faceIndex=w,a&&(a.point?a.point.copy(x):a.point=x.clone(),a.point.applyMatrix4(Wl),_.applyMatrix4(Wl),a.distance=_.sub(a.point).length(),a.faceIndex=p),n)}function lu(i,t,e){return i===null?null:(i.point.applyMatrix4(t.matrixWorld),i.distance=i.point.distanceTo(e.ray.origin),i.object=t,i)}var jl=new Ie,Xl=new qp,Eg=new it,Tg=new Ke,Ig=new it,hu=["getX","getY","getZ"],ql=class i extends Dl{static serialize(t,e={}){e={cloneBuffers:!0,...e};let n=t.geometry,a=t._roots,s=t._indirectBuffer,r=n.getIndex(),o={version:1,roots:null,index:null,indirectBuffer:null};return e.cloneBuffers?(o.roots=a.map(c=>c.slice()),o.index=r?r.array.slice():null,o.indirectBuffer=s?s.slice():null):(o.roots=a,o.index=r?r.array:null,o.indirectBuffer=s),o}static deserialize(t,e,n={}){n={setIndex:!0,indirect:!!t.indirectBuffer,...n};let{index:a,roots:s,indirectBuffer:r}=t;t.version||(console.warn("MeshBVH.deserialize: Serialization format has been changed and will be fixed up. It is recommended to regenerate any stored serialized data."),c(s));let o=new i(e,{...n,[Yr]:!0});if(o._roots=s,o._indirectBuffer=r||null,n.setIndex){let l=e.getIndex();if(l===null){let h=new ze(t.index,1,!1);e.setIndex(h)}else l.array!==a&&(l.array.set(a),l.needsUpdate=!0)}return o;function c(l){for(let h=0;h<l.length;h++){let u=l[h],d=new Uint32Array(u),f=new Uint16Array(u);for(let b=0,_=u.byteLength/32;b<_;b++){let m=8*b,x=2*m;ee(x,f)||(d[m+6]=d[m+6]/8-b)}}}}get primitiveStride(){return 3}get resolveTriangleIndex(){return this.resolvePrimitiveIndex}constructor(t,e={}){e.maxLeafTris&&(console.warn('MeshBVH: "maxLeafTris" option has been deprecated. Use "targetLeafSize", instead.'),e={...e,targetLeafSize:e.maxLeafTris}),super(t,e)}shiftTriangleOffsets(t){return super.shiftPrimitiveOffsets(t)}writePrimitiveBounds(t,e,n){let a=this.geometry,s=this._indirectBuffer,r=a.attributes.position,o=a.index?a.index.array:null,l=(s?s[t]:t)*3,h=l+0,u=l+1,d=l+2;o&&(h=o[h],u=o[u],d=o[d]);for(let f=0;f<3;f++){let b=r[hu[f]](h),_=r[hu[f]](u),m=r[hu[f]](d),x=b;_<x&&(x=_),m<x&&(x=m);let v=b;_>v&&(v=_),m>v&&(v=m),e[n+f]=x,e[n+f+3]=v}return e}computePrimitiveBounds(t,e,n){let a=this.geometry,s=this._indirectBuffer,r=a.attributes.position,o=a.index?a.index.array:null,c=r.normalized;if(t<0||e+t-n.offset>n.length/6)throw new Error("MeshBVH: compute triangle bounds range is invalid.");let l=r.array,h=r.offset||0,u=3;r.isInterleavedBufferAttribute&&(u=r.data.stride);let d=["getX","getY","getZ"],f=n.offset;for(let b=t,_=t+e;b<_;b++){let x=(s?s[b]:b)*3,v=(b-f)*6,w=x+0,p=x+1,y=x+2;o&&(w=o[w],p=o[p],y=o[y]),c||(w=w*u+h,p=p*u+h,y=y*u+h);for(let S=0;S<3;S++){let g,M,E;c?(g=r[d[S]](w),M=r[d[S]](p),E=r[d[S]](y)):(g=l[w+S],M=l[p+S],E=l[y+S]);let A=g;M<A&&(A=M),E<A&&(A=E);let I=g;M>I&&(I=M),E>I&&(I=E);let C=(I-A)/2,P=S*2;n[v+P+0]=A+C,n[v+P+1]=C+(Math.abs(A)+C)*Ss}}return n}raycastObject3D(t,e,n=[]){let{material:a}=t;if(a===void 0)return;Tg.copy(t.matrixWorld).invert(),Xl.copy(e.ray).applyMatrix4(Tg),Ig.setFromMatrixScale(t.matrixWorld),Eg.copy(Xl.direction).multiply(Ig);let s=Eg.length(),r=e.near/s,o=e.far/s;if(e.firstHitOnly===!0){let c=this.raycastFirst(Xl,a,r,o);c=lu(c,t,e),c&&n.push(c)}else{let c=this.raycast(Xl,a,r,o);for(let l=0,h=c.length;l<h;l++){let u=lu(c[l],t,e);u&&n.push(u)}}return n}refit(t=null){return(this.indirect?_g:dg)(this,t)}raycast(t,e=pi,n=0,a=1/0){let s=this._roots,r=[],o=this.indirect?vg:mg;for(let c=0,l=s.length;c<l;c++)o(this,c,e,t,r,n,a);return r}raycastFirst(t,e=pi,n=0,a=1/0){let s=this._roots,r=null,o=this.indirect?Mg:gg;for(let c=0,l=s.length;c<l;c++){let h=o(this,c,e,t,n,a);h!=null&&(r==null||h.distance<r.distance)&&(r=h)}return r}intersectsGeometry(t,e){let n=!1,a=this._roots,s=this.indirect?wg:xg;for(let r=0,o=a.length;r<o&&(n=s(this,r,t,e),!n);r++);return n}shapecast(t){let e=vn.getPrimitive(),n=super.shapecast({...t,intersectsPrimitive:t.intersectsTriangle,scratchPrimitive:e,iterate:this.indirect?pg:hg});return vn.releasePrimitive(e),n}bvhcast(t,e,n){let{intersectsRanges:a,intersectsTriangles:s}=n,r=vn.getPrimitive(),o=this.geometry.index,c=this.geometry.attributes.position,l=this.indirect?b=>{let _=this.resolveTriangleIndex(b);ve(r,_*3,o,c)}:b=>{ve(r,b*3,o,c)},h=vn.getPrimitive(),u=t.geometry.index,d=t.geometry.attributes.position,f=t.indirect?b=>{let _=t.resolveTriangleIndex(b);ve(h,_*3,u,d)}:b=>{ve(h,b*3,u,d)};if(s){if(!(t instanceof i))throw new Error('MeshBVH: "intersectsTriangles" callback can only be used with another MeshBVH.');let b=(_,m,x,v,w,p,y,S)=>{for(let g=x,M=x+v;g<M;g++){f(g),h.a.applyMatrix4(e),h.b.applyMatrix4(e),h.c.applyMatrix4(e),h.needsUpdate=!0;for(let E=_,A=_+m;E<A;E++)if(l(E),r.needsUpdate=!0,s(r,h,E,g,w,p,y,S))return!0}return!1};if(a){let _=a;a=function(m,x,v,w,p,y,S,g){return _(m,x,v,w,p,y,S,g)?!0:b(m,x,v,w,p,y,S,g)}}else a=b}return super.bvhcast(t,e,{intersectsRanges:a})}intersectsBox(t,e){return jl.set(t.min,t.max,e),jl.needsUpdate=!0,this.shapecast({intersectsBounds:n=>jl.intersectsBox(n),intersectsTriangle:n=>jl.intersectsTriangle(n)})}intersectsSphere(t){return this.shapecast({intersectsBounds:e=>t.intersectsBox(e),intersectsTriangle:e=>e.intersectsSphere(t)})}closestPointToGeometry(t,e,n={},a={},s=0,r=1/0){return(this.indirect?Ag:yg)(this,t,e,n,a,s,r)}closestPointToPoint(t,e={},n=0,a=1/0){return ng(this,t,e,n,a)}};var sS=4;function Rg({stage:i,surface:t,root:e,canPick:n,culled:a,frame:s,onPick:r}){let o=new ml,c=new ln,l=null,h=null,u=null;function d(){return!l&&t.geometry()&&(l=new ql(t.geometry(),{indirect:!0,targetLeafSize:32})),l}function f(){let w=globalThis.requestIdleCallback||(S=>setTimeout(S,200)),p=globalThis.cancelIdleCallback||clearTimeout,y=w(()=>{h=null,d()},{timeout:3e3});h=()=>p(y)}function b(w,p){if(!t.mesh()||!d())return-1;let y=i.canvas.getBoundingClientRect();c.set((w-y.left)/y.width*2-1,-((p-y.top)/y.height)*2+1),o.setFromCamera(c,i.camera);let S=l.raycastFirst(o.ray,a()?pi:Li);if(!S)return-1;let{offset:g,scale:M}=s();return e.dataset.pickPoint=S.point.toArray().map((E,A)=>E/M+g[A]).join(","),S.faceIndex}function _(w){u=w.button===0?[w.clientX,w.clientY]:null}function m(w){if(!u||Math.hypot(w.clientX-u[0],w.clientY-u[1])>sS||(u=null,!n))return;let p=b(w.clientX,w.clientY);p>=0&&r(p)}let x=ys(i.canvas,{pointerdown:_,pointerup:m});function v(){h&&h(),l=h=null}return{schedule:f,clear:v,dispose(){v(),x()}}}function rS(){let i=new jp({side:Li,flatShading:!0,polygonOffset:!0,polygonOffsetFactor:1,polygonOffsetUnits:1}),t={value:new kn};return i.onBeforeCompile=e=>{let n="vec4 diffuseColor = vec4( diffuse, opacity );";if(!e.fragmentShader.includes(n))throw new Error("mesh view: three.js's Lambert shader changed");e.uniforms.backDiffuse=t,e.fragmentShader=`uniform vec3 backDiffuse;
`+e.fragmentShader.replace(n,"vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );")},i.customProgramCacheKey=()=>"trinormal-two-sided",{material:i,backColor:t.value}}function Cg(i){let{material:t,backColor:e}=rS(),n=null,a=null;function s(c,l,h){return n=new Zn,n.setAttribute("position",new ze(c,3)),n.setIndex(new ze(l,1)),h&&h.length===c.length&&n.setAttribute("normal",new ze(h,3)),n.computeBoundingSphere(),a=new cn(n,t),i.add(a),n}function r(c,l){let h=c?pi:Li;l&&n&&!n.getAttribute("normal")&&n.computeVertexNormals(),(t.side!==h||t.flatShading===l)&&(t.side=h,t.flatShading=!l,t.needsUpdate=!0)}function o(){a&&i.remove(a),n&&n.dispose(),n=a=null}return{material:t,geometry:()=>n,mesh:()=>a,draw:s,shade:r,setColors(c,l){t.color=new kn(c),e.set(l)},clear:o,dispose(){o(),t.dispose()}}}var du={cull:!1,smooth:!1,show_face_normals:!0,show_vertex_normals:!1},oS=[["cull","Cull back faces","Hide the back of every face, as a game engine does: flipped faces vanish"],["smooth","Smooth shading","Light each face with its corners' vertex normals blended, instead of one normal per face"],["show_face_normals","Face normals","Show each face's unit normal as an arrow from its centre"],["show_vertex_normals","Vertex normals","Show the vertex normals as arrows from the vertices"]];function Ng(i,t){let e={...du},n=a=>i.get(a)!==void 0&&i.get(a)!==null;return{get:a=>n(a)?!!i.get(a):e[a],set(a,s){e[a]=s,n(a)?(i.set(a,s),i.save_changes()):t()}}}function Pg({flags:i,stage:t}){let e=bl("tnm-toolbar","3D view of the mesh"),n={};for(let[s,r,o]of oS){let c=Xt("button","tnm-button",r);c.type="button",c.setAttribute("aria-pressed","false"),c.title=o,c.addEventListener("click",()=>i.set(s,!i.get(s))),n[s]=c}n.show_face_normals.hidden=n.show_vertex_normals.hidden=!0;let a=Xt("button","tnm-button","Reset view");return a.type="button",a.addEventListener("click",()=>t.reset()),e.append(a,...Object.values(n)),{el:e,update(s){for(let[r,o]of Object.entries(n))o.setAttribute("aria-pressed",String(i.get(r)));n.show_face_normals.hidden=!s.has("face"),n.show_vertex_normals.hidden=!s.has("vertex")}}}var Lg=".tnm-toolbar{display:flex;flex-wrap:wrap;gap:6px;margin:0 0 6px}.tnm-button{font:inherit;font-size:14px;line-height:1.2;padding:6px 9px;min-height:34px;border-radius:6px;cursor:pointer;border:1px solid var(--tn-muted);background:var(--tn-bg);color:var(--tn-fg)}.tnm-button[aria-pressed=true]{background:var(--tn-fg);color:var(--tn-bg)}.tnm-button:focus-visible,.tnm-face-input:focus-visible{outline:3px solid #0072B2;outline-offset:2px}.tnm-stage{position:relative;width:100%;height:380px;max-height:70vh;min-height:220px;border:1px solid var(--tn-muted);border-radius:0;overflow:hidden;touch-action:pan-y}.tnm-stage:focus-visible{outline:3px solid #0072B2;outline-offset:-3px}.tnm-touch-active .tnm-stage{touch-action:none;outline:3px solid #0072B2;outline-offset:-3px}.tnm-stage canvas{display:block;width:100%;height:100%}.tnm-legend{list-style:none;margin:6px 0 0;padding:0;display:flex;flex-wrap:wrap;gap:4px 16px;font-size:14px}.tnm-key{display:flex;align-items:center;gap:6px;margin:0}.tnm-swatch{display:inline-block;flex:none;width:18px;border:1px solid var(--tn-muted)}.tnm-swatch-face{height:14px;background:var(--tnm-swatch)}.tnm-swatch-line{height:0;border:0;border-top:4px solid var(--tnm-swatch)}.tnm-hint{font-size:14px;margin:6px 0 0;color:var(--tn-muted)}.tnm-nogl{padding:12px;border:1px solid var(--tn-muted)}.tnm-pick{margin:6px 0 0;padding:6px 10px;border:1px solid var(--tn-muted);border-radius:6px;font-size:15px}.tnm-pick-title{margin:0 0 4px;font-weight:600}.tnm-pick-rows{display:grid;grid-template-columns:max-content 1fr;gap:2px 12px;margin:0}.tnm-pick-rows dt{margin:0}.tnm-pick-rows dd{margin:0;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;overflow-wrap:anywhere}.tnm-keys{display:flex;flex-wrap:wrap;align-items:center;gap:6px;margin:6px 0 0}.tnm-keys[hidden]{display:none}.tnm-face-label{font-size:14px}.tnm-face-input{font:inherit;font-size:15px;width:8.5em;min-height:34px;padding:4px 6px;border:1px solid var(--tn-muted);border-radius:6px;background:var(--tn-bg);color:var(--tn-fg)}.tnm-button[hidden]{display:none}";var Dg={flipped:0,boundary:0,non_manifold:0,face_arrows:0,vertex_arrows:0};function lS(i){return Xt("p","tnm-hint","Drag to turn the model, scroll or pinch to zoom; on a touch screen, tap the view first, then drag; from the keyboard, Tab to the view and use the arrow keys, + and −. The side a face's normal points out of is drawn in the front colour; a face you see in the back colour from outside is wound the other way."+(i?" Click or tap a face, or type its number in the Face number box, to see its vertices, its exact normal and its area.":""))}function hS(i,t){let e=Xt("div","tn-view tnm-root"),n=Xt("div","tnm-stage"),a=Xt("ul","tnm-legend"),s=Xt("div","tnm-pick");return s.setAttribute("aria-live","polite"),s.setAttribute("aria-atomic","true"),s.hidden=!0,t.form.hidden=!i,e.append(n,a,t.form,s,lS(i)),{root:e,stageEl:n,legend:a,panel:s}}function Fs(i,t){return Xr(i.model.get("palette")||{},t,i.dark)}function Ug(i){Vm(i.legend,{counts:i.counts,shown:t=>i.flags.get(t==="face_arrows"?"show_face_normals":"show_vertex_normals"),colorOf:t=>t==="face_arrows"?Fs(i,"N"):t==="vertex_arrows"?Qi(i.dark).text:Fs(i,t)})}function uu(i){let t=Qi(i.dark);i.root.classList.toggle("tn-dark",i.dark),i.stage.setBackground(t.background),i.surface.setColors(Fs(i,"front"),Fs(i,"back")),i.outlines.setColors(e=>Fs(i,e),t.line),i.arrows.setColors(Fs(i,"N"),t.text),Ug(i),i.stage.requestRender()}function Yl(i){let{flags:t,current:e}=i;i.surface.shade(t.get("cull"),t.get("smooth")),i.arrows.show("face",t.get("show_face_normals")),i.arrows.show("vertex",t.get("show_vertex_normals")),i.toolbar.update(i.arrows);let n=e?e.data.faces.length/3:0;i.faceForm.form.hidden=!i.canPick||!n,i.faceForm.update(n,e&&e.data.flipped),Ug(i),i.stage.requestRender()}function Og(i){let{width:t,height:e}=i.stage.size();i.outlines.setResolution(t,e)}function dS(i){for(let t of[i.surface,i.outlines,i.arrows,i.lod,i.picking])t.clear();i.current=null,i.counts=Dg}function uS(i){dS(i);let{root:t,stage:e}=i,n=Am(i.model);if(!n||!n.positions||!n.faces){Yl(i);return}let{pos:a,offset:s,scale:r}=Em(n.positions);i.surface.draw(a,n.faces,n.vertex_normals),i.picking.schedule();let o=km(n,a.length/3);t.dataset.flippedSides=String(o.flipped.length),i.outlines.draw(a,n.faces,o),i.outlines.show(!1),e.framePoints(Tm(a),!0,Im(a,n.faces,o)),i.lod.draw(n.faces,a),i.arrows.draw(n,a),i.counts={flipped:n.flipped?n.flipped.length:0,boundary:o.boundary.length,non_manifold:o.non_manifold.length,face_arrows:i.arrows.count("face"),vertex_arrows:i.arrows.count("vertex")},i.current={data:n,pos:a,offset:s,scale:r},Og(i),Yl(i),t.dataset.faces=String(n.faces.length/3),fu(i)}function fu(i){let{model:t,current:e,root:n}=i;i.outlines.clearPicked();let a=t.get("picked");e&&Number.isInteger(a)&&a>=0&&a<e.data.faces.length/3?(i.outlines.showPicked(e.pos,e.data.faces,a),n.dataset.picked=String(a),i.faceForm.showPicked(a)):delete n.dataset.picked,Hm(i.panel,t.get("selection")),i.stage.requestRender()}function fS({model:i,el:t}){let e=t.ownerDocument||document,n=i.get("picked")!==void 0;_l(e,"trinormal-mesh-style",Lg);let a=Cm({onPick:f,picked:()=>i.get("picked")}),{root:s,stageEl:r,legend:o,panel:c}=hS(n,a);t.appendChild(s);let l;try{l=yl(r,{onRender:()=>{}})}catch{return r.remove(),s.appendChild(Xt("p","tnm-nogl","This browser cannot draw the 3D view (WebGL is not available). The report above does not need it.")),()=>s.remove()}let h=new Hp(16777215,1.9);h.position.set(0,0,1),l.camera.add(h),l.scene.add(new kp(16777215,1.1),l.camera);let u={model:i,root:s,stage:l,legend:o,panel:c,faceForm:a,canPick:n,dark:_s(e),current:null,counts:Dg};u.flags=Ng(i,()=>Yl(u)),u.surface=Cg(l.scene),u.outlines=zm(l.scene),u.arrows=wm(l.scene),u.lod=Pm({stage:l,surface:u.surface,outlines:u.outlines,root:s});let d=()=>u.flags.get("cull");u.picking=Rg({stage:l,surface:u.surface,root:s,canPick:n,culled:d,frame:()=>u.current,onPick:f}),u.toolbar=Pg({flags:u.flags,stage:l}),s.prepend(u.toolbar.el);function f(g){i.set("picked",g),i.save_changes(),fu(u)}let b=Rm(r,l),_=Ml({root:s,stageEl:r,controls:l.controls,canvas:l.canvas,activeClass:"tnm-touch-active"}),m=new ResizeObserver(()=>{Og(u),l.requestRender()});m.observe(r);let x=vl(g=>{u.dark=g,uu(u)},e),v=()=>uS(u),w=()=>Yl(u),p=()=>uu(u),y=()=>fu(u),S=[["change:mesh",v],["change:revision",v],["change:palette",p],["change:picked",y],["change:selection",y],...Object.keys(du).map(g=>["change:"+g,w])];for(let[g,M]of S)i.on(g,M);return uu(u),v(),()=>{for(let[g,M]of S)i.off(g,M);b(),_.dispose(),m.disconnect(),x();for(let g of[u.picking,u.lod,u.surface,u.outlines,u.arrows])g.dispose();l.dispose(),s.remove()}}var pu={render:fS};function pS(i){return(i.model.get("_view")==="mesh"?pu:Fd).render(i)}var mS={render:pS};return Ra(gS);})();
return tnxModule})());
export default R.default;
export const explorer=R.explorer,mesh=R.mesh;
